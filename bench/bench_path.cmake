grape_bench(path grape::path grape_scenes)
