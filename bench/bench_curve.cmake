grape_bench(curve grape::curve grape::anim)
