grape_bench(anim grape::anim grape_scenes)
