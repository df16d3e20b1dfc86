# bench_dynamics: steps per second of a bead, a constrained particle and chains of 10, 100
# and 1,000 particles, with the same chains in Box2D 2.4 (libbox2d-dev) in the same run.
find_package(box2d 2.4 REQUIRED)
grape_bench(dynamics grape::dynamics grape_scenes box2d::box2d)
