grape_bench(timeline grape::anim grape_scenes)
