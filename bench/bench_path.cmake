grape_bench(path grape::path grape_scenes)
grape_bench(path_query grape::path grape_scenes)
