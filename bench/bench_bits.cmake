# bench_bits: BitVector against boost::dynamic_bitset (libboost-dev, header-only),
# std::vector<bool>, std::bitset and memcpy. bench_sprite: 1,000,000 SpritePlayers per frame.
find_package(Boost 1.74 REQUIRED)
grape_bench(bits grape::bits Boost::headers)
grape_bench(sprite grape::sprite)
