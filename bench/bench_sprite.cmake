# bench_sprite: a million SpritePlayers and ClipPlayers per frame against compare-and-subtract
# accumulators doing the same work.
grape_bench(sprite grape::sprite)
