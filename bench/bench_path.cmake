grape_bench(path grape::path grape::path_internal grape_scenes)
grape_bench(path_query grape::path grape_scenes)
grape_bench(path3 grape::path)
