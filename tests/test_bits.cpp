// Tests for grape::BitVector, PairBits and KeyState. The truth is a std::vector<bool> model
// driven by the same random operations, closed forms (pair indices, counts) and invariants.
#include <grape/bits.hpp>
#include <grape/error.hpp>

#include "../src/bits/word_kernels.hpp"

#include "error_text.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <iterator>
#include <ranges>
#include <random>
#include <sstream>
#include <string>
#include <unordered_set>
#include <vector>

namespace {

using grape::BitVector;
using grape::KeyState;
using grape::PairBits;

using grape::testing::expect_error;

using Model = std::vector<bool>;

// The unused bits of the last word must be zero: that is what keeps them out of count,
// all, ~, == and hash.
bool tail_is_clear(const BitVector& v) {
    const auto words = v.words();
    if (v.size() % 64 == 0) return words.size() == v.size() / 64;
    if (words.size() != v.size() / 64 + 1) return false;
    return (words.back() >> (v.size() % 64)) == 0;
}

void expect_matches(const BitVector& v, const Model& m) {
    ASSERT_EQ(v.size(), m.size());
    ASSERT_TRUE(tail_is_clear(v));
    std::size_t ones = 0;
    std::vector<std::size_t> expected_set;
    std::string expected_string;
    for (std::size_t i = 0; i < m.size(); ++i) {
        ASSERT_EQ(v.get(i), static_cast<bool>(m[i])) << "bit " << i;
        if (m[i]) {
            ++ones;
            expected_set.push_back(i);
        }
        expected_string += m[i] ? '1' : '0';
    }
    EXPECT_EQ(v.count(), ones);
    EXPECT_EQ(v.any(), ones > 0);
    EXPECT_EQ(v.none(), ones == 0);
    EXPECT_EQ(v.all(), ones == m.size());
    EXPECT_EQ(v.to_string(), expected_string);

    std::vector<std::size_t> by_find;
    for (std::size_t i = v.find_first(); i != BitVector::npos; i = v.find_next(i)) by_find.push_back(i);
    EXPECT_EQ(by_find, expected_set);
    std::vector<std::size_t> by_range;
    for (std::size_t i : v.set_bits()) by_range.push_back(i);
    EXPECT_EQ(by_range, expected_set);
    std::vector<std::size_t> by_each;
    v.for_each_set([&](std::size_t i) { by_each.push_back(i); });
    EXPECT_EQ(by_each, expected_set);
}

BitVector from_model(const Model& m) {
    BitVector v(m.size());
    for (std::size_t i = 0; i < m.size(); ++i) v.set(i, m[i]);
    return v;
}

Model random_model(std::mt19937_64& rng, std::size_t size, double density) {
    std::bernoulli_distribution bit(density);
    Model m(size);
    for (std::size_t i = 0; i < size; ++i) m[i] = bit(rng);
    return m;
}

const std::size_t edge_sizes[] = {0, 1, 2, 63, 64, 65, 127, 128, 129, 191, 255, 256, 257, 1000, 4099};

TEST(BitVector, ConstructionFillsAndKeepsTheTailClear) {
    for (std::size_t n : edge_sizes) {
        for (bool value : {false, true}) {
            BitVector v(n, value);
            expect_matches(v, Model(n, value));
            EXPECT_EQ(v.empty(), n == 0);
        }
    }
    BitVector empty;
    EXPECT_EQ(empty.size(), 0u);
    EXPECT_TRUE(empty.all());  // vacuous truth, as std::all_of
    EXPECT_TRUE(empty.none());
    EXPECT_EQ(empty.find_first(), BitVector::npos);
    EXPECT_EQ(empty.find_next(BitVector::npos), BitVector::npos);
}

// Every operation, randomly interleaved, against the std::vector<bool> model.
TEST(BitVector, RandomOperationsMatchVectorOfBool) {
    std::mt19937_64 rng(20261122);
    for (int trial = 0; trial < 300; ++trial) {
        std::size_t n = trial < 15 ? edge_sizes[trial] : std::uniform_int_distribution<std::size_t>(0, 700)(rng);
        const double density = std::uniform_real_distribution<double>(0.0, 1.0)(rng);
        Model m = random_model(rng, n, density);
        BitVector v = from_model(m);
        expect_matches(v, m);
        for (int op = 0; op < 40; ++op) {
            const int kind = std::uniform_int_distribution<int>(0, 13)(rng);
            const std::size_t i = n == 0 ? 0 : std::uniform_int_distribution<std::size_t>(0, n - 1)(rng);
            switch (kind) {
                case 0:
                    if (n) { v.set(i); m[i] = true; }
                    break;
                case 1:
                    if (n) { v.reset(i); m[i] = false; }
                    break;
                case 2:
                    if (n) { v.flip(i); m[i] = !m[i]; }
                    break;
                case 3:
                    if (n) { EXPECT_EQ(v.test_and_set(i), static_cast<bool>(m[i])); m[i] = true; }
                    break;
                case 4: v.set_all(); m.assign(n, true); break;
                case 5: v.clear_all(); m.assign(n, false); break;
                case 6: v.flip_all(); m.flip(); break;
                case 7: case 8: case 9: case 10: {
                    const Model o = random_model(rng, n, std::uniform_real_distribution<double>(0.0, 1.0)(rng));
                    const BitVector ov = from_model(o);
                    for (std::size_t k = 0; k < n; ++k) {
                        const bool a = m[k], b = o[k];
                        m[k] = kind == 7 ? (a && b) : kind == 8 ? (a || b) : kind == 9 ? (a != b) : (a && !b);
                    }
                    // Alternate between compound and binary forms.
                    if (op % 2 == 0) {
                        if (kind == 7) v &= ov; else if (kind == 8) v |= ov; else if (kind == 9) v ^= ov; else v.subtract(ov);
                    } else {
                        if (kind == 7) v = v & ov; else if (kind == 8) v = v | ov; else if (kind == 9) v = v ^ ov; else v.subtract(ov);
                    }
                    break;
                }
                case 11: {
                    v = ~v;
                    m.flip();
                    break;
                }
                case 12: {
                    const std::size_t to = std::uniform_int_distribution<std::size_t>(0, 800)(rng);
                    const bool value = std::bernoulli_distribution(0.5)(rng);
                    v.resize(to, value);
                    m.resize(to, value);
                    n = to;
                    break;
                }
                case 13: {
                    const Model o = random_model(rng, n, 0.05);
                    const BitVector ov = from_model(o);
                    bool subset = true, meets = false;
                    for (std::size_t k = 0; k < n; ++k) {
                        if (o[k] && !m[k]) subset = false;
                        if (o[k] && m[k]) meets = true;
                    }
                    EXPECT_EQ(ov.is_subset_of(v), subset);
                    EXPECT_EQ(ov.intersects(v), meets);
                    break;
                }
            }
            expect_matches(v, m);
            if (HasFatalFailure()) return;
        }
        EXPECT_EQ(v, from_model(m));
    }
}

TEST(BitVector, OperandMayBeTheVectorItself) {
    std::mt19937_64 rng(7);
    const Model m = random_model(rng, 333, 0.4);
    BitVector v = from_model(m);
    const BitVector& same = v;  // the operand is v itself, under a second name
    v &= same;
    expect_matches(v, m);
    v |= same;
    expect_matches(v, m);
    v ^= same;
    EXPECT_TRUE(v.none());
}

TEST(BitVector, ResizeGivesNewBitsTheValueAndDropsCutBits) {
    BitVector v(70, true);
    v.resize(10);  // cut 60 ones...
    v.resize(70);  // ...and grow back with zeros: the ones must not come back
    EXPECT_EQ(v.count(), 10u);
    EXPECT_EQ(v, BitVector::from_string(std::string(10, '1') + std::string(60, '0')));
    BitVector w(3);
    w.resize(200, true);  // grows through the partial first word into new words
    EXPECT_EQ(w.count(), 197u);
    EXPECT_EQ(w.to_string(), "000" + std::string(197, '1'));
    w.reserve(10'000);
    EXPECT_GE(w.memory_bytes(), 10'000u / 8);
    EXPECT_EQ(w.size(), 200u);
}

TEST(BitVector, SetBitsIsAForwardRange) {
    static_assert(std::forward_iterator<BitVector::SetBitIterator>);
    static_assert(std::ranges::forward_range<BitVector::SetBits>);
    const BitVector v = BitVector::from_string("0110000000000000000000000000000000000000000000000000000000000000000000001");
    const auto bits = v.set_bits();
    EXPECT_EQ(std::ranges::distance(bits), 3);
    auto it = bits.begin();
    const auto first = it++;  // post-increment returns the old position
    EXPECT_EQ(*first, 1u);
    EXPECT_EQ(*it, 2u);
    EXPECT_TRUE(first != it);
    EXPECT_TRUE(bits.begin() == first);
    EXPECT_EQ(*std::ranges::next(bits.begin(), 2), 72u);
    EXPECT_TRUE(std::ranges::next(bits.begin(), 3) == bits.end());
    EXPECT_TRUE(BitVector(500).set_bits().begin() == std::default_sentinel);  // all zero words
    EXPECT_TRUE(BitVector().set_bits().begin() == std::default_sentinel);     // no words at all
}

TEST(BitVector, FindNextFromAnyIndex) {
    const BitVector v = BitVector::from_string("0100000000000000000000000000000000000000000000000000000000000000001001");
    EXPECT_EQ(v.find_first(), 1u);
    EXPECT_EQ(v.find_next(0), 1u);
    EXPECT_EQ(v.find_next(1), 66u);
    EXPECT_EQ(v.find_next(66), 69u);
    EXPECT_EQ(v.find_next(69), BitVector::npos);
    EXPECT_EQ(v.find_next(1000), BitVector::npos);
    EXPECT_EQ(v.find_next(BitVector::npos), BitVector::npos);
}

TEST(BitVector, StringFormRoundTripsAndNamesBadCharacters) {
    std::mt19937_64 rng(11);
    for (std::size_t n : edge_sizes) {
        const BitVector v = from_model(random_model(rng, n, 0.5));
        EXPECT_EQ(BitVector::from_string(v.to_string()), v);
        std::ostringstream out;
        out << v;
        EXPECT_EQ(out.str(), v.to_string());
    }
    EXPECT_EQ(BitVector::from_string("1000").find_first(), 0u);  // bit 0 is written first
    expect_error([] { (void)BitVector::from_string("0110x1"); }, {"from_string", "bits[4]", "'x'", "'0' or '1'"});
}

TEST(BitVector, CheckedAtNamesIndexAndSize) {
    const BitVector v = BitVector::from_string("0010");
    EXPECT_TRUE(v.at(2));
    EXPECT_FALSE(v.at(3));
    expect_error([&] { (void)v.at(4); }, {"BitVector::at", "index 4", "size 4"});
    expect_error([&] { (void)BitVector().at(0); }, {"index 0", "size 0"});
}

TEST(BitVector, SizeMismatchThrowsNamingTheOperation) {
    BitVector a(10), b(11);
    expect_error([&] { a &= b; }, {"operator&=", "size 11", "(10)"});
    expect_error([&] { a |= b; }, {"operator|=", "size 11"});
    expect_error([&] { a ^= b; }, {"operator^=", "size 11"});
    expect_error([&] { (void)(a & b); }, {"operator&="});
    expect_error([&] { (void)(a | b); }, {"operator|="});
    expect_error([&] { (void)(a ^ b); }, {"operator^="});
    expect_error([&] { a.subtract(b); }, {"subtract", "size 11"});
    expect_error([&] { (void)a.is_subset_of(b); }, {"is_subset_of"});
    expect_error([&] { (void)a.intersects(b); }, {"intersects"});
    expect_error([&] { a.resize(static_cast<std::size_t>(-1)); }, {"resize", "too large"});
    // Failed operations leave the vector unchanged.
    EXPECT_EQ(a, BitVector(10));
}

TEST(BitVector, EqualityAndHashIgnoreHistory) {
    // The same bits reached by different paths compare and hash equal.
    BitVector a(100, true);
    a.resize(37);
    BitVector b(37);
    b.set_all();
    BitVector c = ~BitVector(37);
    EXPECT_EQ(a, b);
    EXPECT_EQ(b, c);
    const std::hash<BitVector> h;
    EXPECT_EQ(h(a), h(b));
    EXPECT_EQ(h(b), h(c));
    // Same words, different sizes: different values.
    EXPECT_NE(BitVector(10), BitVector(11));
    EXPECT_NE(h(BitVector(10)), h(BitVector(11)));
}

TEST(BitVector, HashSeparatesSingleBitChanges) {
    // Every single-bit variant of a random 1,000-bit vector, plus the size variants, must
    // hash apart: with a 64-bit hash a collision among ~1,000 values has probability ~3e-14,
    // so a collision here means the mixing is broken (e.g. a word or a bit ignored).
    std::mt19937_64 rng(99);
    const BitVector base = from_model(random_model(rng, 1000, 0.5));
    std::unordered_set<BitVector> set;
    std::unordered_set<std::size_t> hashes;
    for (std::size_t i = 0; i < base.size(); ++i) {
        BitVector v = base;
        v.flip(i);
        set.insert(v);
        hashes.insert(std::hash<BitVector>{}(v));
    }
    EXPECT_EQ(set.size(), base.size());
    EXPECT_EQ(hashes.size(), base.size());
    EXPECT_EQ(set.count(base), 0u);
}

// Each instruction-set version of the word loops against a scalar loop, on lengths that
// exercise the vector body and the scalar tail.
TEST(BitVector, EveryKernelVersionAgreesWithScalarLoops) {
    std::size_t versions = 0;
    const grape::detail::WordKernels* const* list = grape::detail::runnable_word_kernels(versions);
    ASSERT_GE(versions, 1u);
    bool selected_is_runnable = false;
    for (std::size_t k = 0; k < versions; ++k) selected_is_runnable |= list[k] == &grape::detail::word_kernels();
    EXPECT_TRUE(selected_is_runnable);
    std::mt19937_64 rng(5);
    for (std::size_t k = 0; k < versions; ++k) {
        const auto& kern = *list[k];
        SCOPED_TRACE(kern.name);
        for (std::size_t n = 0; n < 80; n += (n < 20 ? 1 : 7)) {
            std::vector<std::uint64_t> a(n), b(n);
            for (auto& w : a) w = rng();
            for (auto& w : b) w = rng();
            std::size_t ones = 0;
            for (auto w : a) ones += static_cast<std::size_t>(std::popcount(w));
            EXPECT_EQ(kern.count(a.data(), n), ones);
            auto check = [&](void (*f)(std::uint64_t*, const std::uint64_t*, std::size_t) noexcept, auto op) {
                std::vector<std::uint64_t> x = a;
                f(x.data(), b.data(), n);
                for (std::size_t i = 0; i < n; ++i) ASSERT_EQ(x[i], op(a[i], b[i])) << "word " << i;
            };
            check(kern.and_with, [](auto x, auto y) { return x & y; });
            check(kern.or_with, [](auto x, auto y) { return x | y; });
            check(kern.xor_with, [](auto x, auto y) { return x ^ y; });
            check(kern.and_not, [](auto x, auto y) { return x & ~y; });
            std::vector<std::uint64_t> x = a;
            kern.flip(x.data(), n);
            for (std::size_t i = 0; i < n; ++i) ASSERT_EQ(x[i], ~a[i]);
        }
    }
}

#ifndef NDEBUG
TEST(BitVectorDeathTest, DebugBuildsAssertIndices) {
    GTEST_FLAG_SET(death_test_style, "threadsafe");
    BitVector v(10);
    EXPECT_DEATH((void)v.get(10), "index out of range");
    EXPECT_DEATH(v.set(10), "index out of range");
    EXPECT_DEATH(v.flip(64), "index out of range");
}
#endif

// ---- PairBits ----

TEST(PairBits, IndexIsABijectionOntoThePairRange) {
    // Every unordered pair gets a distinct index in [0, n(n−1)/2): for all n ≤ 160 and for
    // larger sizes around powers of two up to 2,000. The seen-bits live in a vector<bool>,
    // independent of PairBits' own storage.
    std::vector<std::size_t> sizes;
    for (std::size_t n = 0; n <= 160; ++n) sizes.push_back(n);
    for (std::size_t n : {255u, 256u, 257u, 511u, 512u, 513u, 1000u, 1023u, 1024u, 1025u, 1999u, 2000u}) sizes.push_back(n);
    for (std::size_t n : sizes) {
        const PairBits pairs(n);
        const std::size_t expected = n < 2 ? 0 : n * (n - 1) / 2;
        ASSERT_EQ(pairs.pair_count(), expected);
        ASSERT_EQ(pairs.object_count(), n);
        std::vector<bool> seen(expected);
        std::size_t next = 0;  // lexicographic order of (i, j) is index order: a stronger check
        for (std::size_t i = 0; i < n; ++i) {
            for (std::size_t j = i + 1; j < n; ++j) {
                const std::size_t k = pairs.index(i, j);
                ASSERT_LT(k, expected) << "n " << n << " pair " << i << "," << j;
                ASSERT_FALSE(seen[k]) << "n " << n << " pair " << i << "," << j;
                seen[k] = true;
                ASSERT_EQ(k, next++);
                ASSERT_EQ(pairs.index(j, i), k);
            }
        }
        ASSERT_EQ(next, expected);
    }
}

TEST(PairBits, TestAndSetInEitherOrder) {
    PairBits pairs(50);
    std::mt19937_64 rng(3);
    std::vector<std::vector<bool>> model(50, std::vector<bool>(50));
    for (int t = 0; t < 3000; ++t) {
        const std::size_t i = rng() % 50, j = rng() % 50;
        if (i == j) continue;
        EXPECT_EQ(pairs.test(j, i), static_cast<bool>(model[i][j]));
        EXPECT_EQ(pairs.test_and_set(i, j), static_cast<bool>(model[i][j]));
        model[i][j] = model[j][i] = true;
        EXPECT_TRUE(pairs.test(j, i));
    }
    std::size_t ones = 0;
    for (std::size_t i = 0; i < 50; ++i)
        for (std::size_t j = i + 1; j < 50; ++j) ones += model[i][j];
    EXPECT_EQ(pairs.bits().count(), ones);
    pairs.set(4, 2, false);
    EXPECT_FALSE(pairs.test(2, 4));
    pairs.clear_all();
    EXPECT_TRUE(pairs.bits().none());
}

TEST(PairBits, ErrorsNameTheIndices) {
    PairBits pairs(5);
    expect_error([&] { (void)pairs.index(3, 3); }, {"PairBits", "both 3"});
    expect_error([&] { (void)pairs.test_and_set(2, 2); }, {"both 2"});
    expect_error([&] { (void)pairs.test(5, 1); }, {"index 5", "object_count 5"});
    expect_error([&] { pairs.set(1, 9); }, {"index 9", "object_count 5"});
    expect_error([] { PairBits huge(static_cast<std::size_t>(-1)); }, {"object_count", "too large"});
    expect_error([] { PairBits one(1); (void)one.index(0, 1); }, {"index 1", "object_count 1"});
}

// ---- KeyState ----

TEST(KeyState, PressReleaseAndEdgesFollowTheFrameTable) {
    KeyState keys;  // SDL scancodes: 0 … 511
    EXPECT_EQ(keys.key_count(), 512u);
    const std::size_t a = 4, space = 44, last = 511;
    // frame 1: press a
    keys.press(a);
    EXPECT_TRUE(keys.is_down(a));
    EXPECT_TRUE(keys.pressed_this_frame(a));
    EXPECT_FALSE(keys.released_this_frame(a));
    keys.end_frame();
    // frame 2: a held (an OS key repeat is not a new press), last pressed
    keys.press(a);
    keys.press(last);
    EXPECT_TRUE(keys.is_down(a));
    EXPECT_FALSE(keys.pressed_this_frame(a));
    EXPECT_TRUE(keys.pressed_this_frame(last));
    keys.end_frame();
    // frame 3: a released; space tapped (down and up within the frame)
    keys.release(a);
    keys.press(space);
    keys.release(space);
    EXPECT_FALSE(keys.is_down(a));
    EXPECT_TRUE(keys.released_this_frame(a));
    EXPECT_FALSE(keys.is_down(space));
    EXPECT_TRUE(keys.pressed_this_frame(space));
    EXPECT_TRUE(keys.released_this_frame(space));
    keys.release(space);  // releasing an up key is not a new release edge... 
    keys.end_frame();
    // frame 4: nothing happens; only `last` is still down
    EXPECT_FALSE(keys.released_this_frame(a));
    EXPECT_FALSE(keys.pressed_this_frame(space));
    EXPECT_FALSE(keys.released_this_frame(space));
    keys.release(space);
    EXPECT_FALSE(keys.released_this_frame(space));  // ...and does not create one
    EXPECT_EQ(keys.down().count(), 1u);
    EXPECT_TRUE(keys.is_down(last));
    // focus lost
    keys.release_all();
    EXPECT_TRUE(keys.down().none());
    EXPECT_TRUE(keys.released_this_frame(last));
    // codes beyond the range are simply never down
    EXPECT_FALSE(keys.is_down(512));
    EXPECT_FALSE(keys.pressed_this_frame(100000));
    EXPECT_FALSE(keys.released_this_frame(512));
}

TEST(KeyState, MasksForCombinations) {
    KeyState keys(128);
    const std::size_t ctrl = 17, shift = 16, s = 83;
    const BitVector save = keys.mask({ctrl, s});
    const BitVector modifiers = keys.mask({ctrl, shift});
    EXPECT_FALSE(keys.all_down(save));
    EXPECT_FALSE(keys.any_down(modifiers));
    keys.press(ctrl);
    EXPECT_FALSE(keys.all_down(save));
    EXPECT_TRUE(keys.any_down(modifiers));
    keys.press(s);
    EXPECT_TRUE(keys.all_down(save));
    keys.press(shift);
    EXPECT_TRUE(keys.all_down(save));  // extra keys down do not break a combination
    EXPECT_TRUE(keys.all_down(keys.mask({})));
    EXPECT_FALSE(keys.any_down(keys.mask({})));
    expect_error([&] { (void)keys.all_down(BitVector(512)); }, {"is_subset_of", "size 128", "(512)"});
    expect_error([&] { (void)keys.any_down(BitVector(5)); }, {"intersects"});
    expect_error([&] { (void)keys.mask({1, 128}); }, {"KeyState::mask", "key 128", "key_count 128"});
}

TEST(KeyState, ErrorsNameTheKey) {
    KeyState keys(10);
    expect_error([&] { keys.press(10); }, {"KeyState::press", "key 10", "key_count 10"});
    expect_error([&] { keys.release(99); }, {"KeyState::release", "key 99"});
    expect_error([] { KeyState none(0); }, {"key_count", "at least 1", "got 0"});
}

}  // namespace
