// Tests for grape::BitVector, PairBits and KeyState. The truth is a std::vector<bool> model
// driven by the same random operations, closed forms (pair indices, counts) and invariants.
#include <grape/bits.hpp>
#include <grape/error.hpp>
#include <grape/sparse_bits.hpp>

#include "../src/bits/word_kernels.hpp"

#include "error_text.hpp"
#include "seeds.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <bitset>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <iterator>
#include <map>
#include <ranges>
#include <random>
#include <span>
#include <sstream>
#include <string>
#include <unordered_set>
#include <utility>
#include <vector>

namespace {

using grape::BitVector;
using grape::KeyState;
using grape::PairBits;
using grape::SparseBitVector;

using grape::testing::expect_error;

using Model = std::vector<bool>;

// std::ranges::distance and std::ranges::next by hand: libc++ 14 has neither.
template <class R>
std::ptrdiff_t distance_of(R&& range) {
    std::ptrdiff_t n = 0;
    for (auto it = range.begin(); it != range.end(); ++it) ++n;
    return n;
}
template <class I>
I next_by(I it, int n) {
    while (n-- > 0) ++it;
    return it;
}

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
    std::mt19937_64 rng(grape::testing::test_seed(20261122));
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
    std::mt19937_64 rng(grape::testing::test_seed(7));
    const Model m = random_model(rng, 333, 0.4);
    BitVector v = from_model(m);
    const BitVector& same = v;  // through a reference, as aliasing happens in real code
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
    EXPECT_EQ(distance_of(bits), 3);
    auto it = bits.begin();
    const auto first = it++;  // post-increment returns the old position
    EXPECT_EQ(*first, 1u);
    EXPECT_EQ(*it, 2u);
    EXPECT_TRUE(first != it);
    EXPECT_TRUE(bits.begin() == first);
    EXPECT_EQ(*next_by(bits.begin(), 2), 72u);
    EXPECT_TRUE(next_by(bits.begin(), 3) == bits.end());
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
    std::mt19937_64 rng(grape::testing::test_seed(11));
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
    std::mt19937_64 rng(grape::testing::test_seed(99));
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
    std::mt19937_64 rng(grape::testing::test_seed(5));
    for (std::size_t k = 0; k < versions; ++k) {
        const auto& kern = *list[k];
        SCOPED_TRACE(kern.name);
        for (std::size_t n = 0; n < 1100; n += (n < 20 ? 1 : n < 80 ? 7 : 331)) {  // past 31 × 4 words too
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
            x = a;
            std::size_t and_ones = 0;
            for (std::size_t i = 0; i < n; ++i) and_ones += static_cast<std::size_t>(std::popcount(a[i] & b[i]));
            EXPECT_EQ(kern.and_count(x.data(), b.data(), n), and_ones);
            for (std::size_t i = 0; i < n; ++i) ASSERT_EQ(x[i], a[i] & b[i]);
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
    std::mt19937_64 rng(grape::testing::test_seed(3));
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


// ---- Ranges, shifts, edits, rank/select, backward search, order: against the model ----

// The model's answers, written with plain loops over std::vector<bool>.
std::size_t model_count(const Model& m, std::size_t first, std::size_t last) {
    std::size_t c = 0;
    for (std::size_t i = first; i < last; ++i) c += m[i];
    return c;
}
std::size_t model_prev(const Model& m, std::size_t i) {  // highest set bit below min(i, size)
    for (std::size_t k = std::min(i, m.size()); k-- > 0;)
        if (m[k]) return k;
    return BitVector::npos;
}
std::size_t model_select(const Model& m, std::size_t k) {
    for (std::size_t i = 0; i < m.size(); ++i)
        if (m[i] && k-- == 0) return i;
    return BitVector::npos;
}
Model model_shift_up(const Model& m, std::size_t n) {
    Model r(m.size());
    for (std::size_t i = 0; i < m.size(); ++i)
        if (i >= n) r[i] = m[i - n];
    return r;
}
Model model_shift_down(const Model& m, std::size_t n) {
    Model r(m.size());
    for (std::size_t i = 0; i < m.size(); ++i)
        if (n < m.size() - i) r[i] = m[i + n];
    return r;
}
// Insertion bit by bit: libc++ 14's vector<bool>::insert shifts a word by its whole width
// (undefined behaviour, which UBSan stops at) when it moves bits back onto a word's start.
void model_insert(Model& m, std::size_t pos, std::size_t count, bool value) {
    Model r;
    r.reserve(m.size() + count);
    for (std::size_t i = 0; i < pos; ++i) r.push_back(m[i]);
    for (std::size_t i = 0; i < count; ++i) r.push_back(value);
    for (std::size_t i = pos; i < m.size(); ++i) r.push_back(m[i]);
    m = std::move(r);
}
// The documented order: shorter first, then the highest differing bit (clear before set).
bool model_less(const Model& a, const Model& b) {
    if (a.size() != b.size()) return a.size() < b.size();
    for (std::size_t i = a.size(); i-- > 0;)
        if (a[i] != b[i]) return b[i];
    return false;
}

// Sizes around the word boundaries, then random ones.
const std::size_t boundary_sizes[] = {0, 1, 63, 64, 65, 127, 128, 129};

TEST(BitVector, RangeShiftEditAndSearchOperationsMatchVectorOfBool) {
    std::mt19937_64 rng(grape::testing::test_seed(20261201));
    auto uniform = [&rng](std::size_t lo, std::size_t hi) { return std::uniform_int_distribution<std::size_t>(lo, hi)(rng); };
    for (int trial = 0; trial < 400; ++trial) {
        std::size_t n = trial < 8 ? boundary_sizes[trial] : uniform(0, 600);
        Model m = random_model(rng, n, std::uniform_real_distribution<double>(0.0, 1.0)(rng));
        BitVector v = from_model(m);
        for (int op = 0; op < 60; ++op) {
            SCOPED_TRACE("trial " + std::to_string(trial) + " op " + std::to_string(op) + " size " + std::to_string(n));
            // Range ends in [0, n], biased to the word boundaries.
            auto end_point = [&] {
                if (uniform(0, 3) != 0) return uniform(0, n);
                const std::size_t near = uniform(0, n / 64 + 1) * 64 + uniform(0, 2);  // 64k − 1, 64k, 64k + 1
                return std::min(n, near == 0 ? 0 : near - 1);
            };
            std::size_t first = end_point(), last = end_point();
            if (first > last) std::swap(first, last);
            const int kind = static_cast<int>(uniform(0, 17));
            switch (kind) {
                case 0: case 1: {
                    const bool value = kind == 0;
                    if (value) v.set_range(first, last); else v.reset_range(first, last);
                    for (std::size_t i = first; i < last; ++i) m[i] = value;
                    break;
                }
                case 2:
                    v.flip_range(first, last);
                    for (std::size_t i = first; i < last; ++i) m[i] = !m[i];
                    break;
                case 3:
                    EXPECT_EQ(v.count_range(first, last), model_count(m, first, last)) << first << " " << last;
                    EXPECT_EQ(v.rank(last), model_count(m, 0, last));
                    break;
                case 4: case 5: {
                    // Shifts: multiples of 64 (a memmove), any amount, and amounts >= size.
                    const std::size_t by = uniform(0, 2) == 0 ? uniform(0, 3) * 64 : uniform(0, n + 70);
                    const bool up = kind == 4;
                    if (op % 2 == 0) {
                        if (up) v <<= by; else v >>= by;
                    } else {
                        v = up ? v << by : v >> by;
                    }
                    m = up ? model_shift_up(m, by) : model_shift_down(m, by);
                    break;
                }
                case 6: {
                    const bool value = uniform(0, 1) == 1;
                    v.push_back(value);
                    m.push_back(value);
                    ++n;
                    break;
                }
                case 7:
                    if (n > 0) {
                        v.pop_back();
                        m.pop_back();
                        --n;
                    }
                    break;
                case 8: {
                    const std::size_t pos = uniform(0, n), count = uniform(0, 3) == 0 ? uniform(0, 200) : uniform(0, 3);
                    const bool value = uniform(0, 1) == 1;
                    if (count == 1 && op % 2 == 0) v.insert(pos, value); else v.insert(pos, count, value);
                    model_insert(m, pos, count, value);
                    n += count;
                    break;
                }
                case 9:
                    if (n > 0 && op % 3 == 0) {
                        const std::size_t pos = uniform(0, n - 1);
                        v.erase(pos);
                        m.erase(m.begin() + static_cast<std::ptrdiff_t>(pos));
                        --n;
                    } else {
                        v.erase(first, last);
                        m.erase(m.begin() + static_cast<std::ptrdiff_t>(first), m.begin() + static_cast<std::ptrdiff_t>(last));
                        n -= last - first;
                    }
                    break;
                case 10: {
                    EXPECT_EQ(v.find_last(), model_prev(m, n));
                    const std::size_t i = uniform(0, n + 3);
                    EXPECT_EQ(v.find_prev(i), model_prev(m, i)) << "below " << i;
                    EXPECT_EQ(v.find_prev(BitVector::npos), model_prev(m, n));
                    break;
                }
                case 11: {
                    const std::size_t ones = model_count(m, 0, n);
                    const std::size_t k = uniform(0, ones + 2);
                    EXPECT_EQ(v.select(k), model_select(m, k)) << "k " << k;
                    if (k < ones) {
                        EXPECT_EQ(v.rank(v.select(k)), k);
                    }
                    break;
                }
                case 12:
                    if (n > 0) {  // the reference proxy: assignment and compound forms
                        const std::size_t i = uniform(0, n - 1), j = uniform(0, n - 1);
                        const bool x = uniform(0, 1) == 1;
                        switch (uniform(0, 5)) {
                            case 0: v[i] = x; m[i] = x; break;
                            case 1: v[i] |= x; m[i] = m[i] || x; break;
                            case 2: v[i] &= x; m[i] = m[i] && x; break;
                            case 3: v[i] ^= x; m[i] = m[i] != x; break;
                            case 4: v[i].flip(); m[i] = !m[i]; break;
                            default: v[i] = v[j]; m[i] = static_cast<bool>(m[j]); break;
                        }
                        EXPECT_EQ(static_cast<bool>(v[i]), static_cast<bool>(m[i]));
                        EXPECT_EQ(~v[j], !m[j]);
                    }
                    break;
                case 13: {  // the order against another vector: same size or not, often equal
                    Model o = uniform(0, 2) == 0 ? random_model(rng, uniform(0, n + 1), 0.5) : m;
                    if (!o.empty() && uniform(0, 1) == 0) o[uniform(0, o.size() - 1)].flip();
                    const BitVector ov = from_model(o);
                    EXPECT_EQ(v < ov, model_less(m, o));
                    EXPECT_EQ(ov < v, model_less(o, m));
                    EXPECT_EQ(v == ov, m == o);
                    EXPECT_EQ((v <=> ov) == 0, m == o);
                    break;
                }
                default: {  // conversions round trip through the model's own type
                    EXPECT_EQ(v.to_bools(), m);
                    EXPECT_EQ(BitVector::from_bools(m), v);
                    break;
                }
            }
            expect_matches(v, m);
            if (HasFatalFailure()) return;
        }
    }
}

TEST(BitVector, RangeErrorsNameTheRange) {
    BitVector v(100);
    expect_error([&] { v.set_range(5, 101); }, {"set_range", "[5, 101)", "size 100"});
    expect_error([&] { v.reset_range(7, 3); }, {"set_range", "[7, 3)", "first > last"});
    expect_error([&] { v.flip_range(0, 200); }, {"flip_range", "[0, 200)"});
    expect_error([&] { (void)v.count_range(101, 101); }, {"count_range", "[101, 101)"});
    expect_error([&] { v.erase(50, 120); }, {"erase", "[50, 120)"});
    expect_error([&] { v.erase(100); }, {"erase", "index 100", "size 100"});
    expect_error([&] { v.insert(101, 3, true); }, {"insert", "position 101", "size 100"});
    expect_error([&] { v.insert(0, static_cast<std::size_t>(-1), true); }, {"insert", "too large"});
    expect_error([&] { (void)v.rank(101); }, {"rank", "index 101", "size 100"});
    expect_error([] { BitVector().pop_back(); }, {"pop_back", "empty"});
    EXPECT_EQ(v, BitVector(100));  // failed operations changed nothing
    EXPECT_EQ(v.select(0), BitVector::npos);
    EXPECT_EQ(BitVector().find_last(), BitVector::npos);
    EXPECT_EQ(BitVector().find_prev(5), BitVector::npos);
    EXPECT_EQ(BitVector().rank(0), 0u);
    v.set_range(100, 100);  // empty ranges at the end are valid
    EXPECT_EQ(v.count_range(0, 0), 0u);
}

TEST(BitVector, ShiftsMoveBitsTowardsHigherAndLowerIndices) {
    // As std::bitset: << moves bit i to i + n.
    const BitVector v = BitVector::from_string("1100000000");
    EXPECT_EQ((v << 3).to_string(), "0001100000");
    EXPECT_EQ((v << 9).to_string(), "0000000001");
    EXPECT_EQ((v << 10).to_string(), "0000000000");
    EXPECT_EQ((BitVector::from_string("0000000011") >> 8).to_string(), "1100000000");
    EXPECT_EQ((v >> static_cast<std::size_t>(-1)).to_string(), "0000000000");
    std::bitset<130> b;
    BitVector w(130);
    for (std::size_t i : {0u, 1u, 63u, 64u, 100u, 129u}) {
        b.set(i);
        w.set(i);
    }
    for (std::size_t by : {0u, 1u, 37u, 63u, 64u, 65u, 128u, 129u, 130u}) {
        EXPECT_EQ(w << by, BitVector::from_bitset(b << by)) << by;
        EXPECT_EQ(w >> by, BitVector::from_bitset(b >> by)) << by;
    }
}

template <class B>
concept inserts_an_int = requires(B b) { b.insert(std::size_t{0}, 5); };

TEST(BitVector, InsertAndEraseKeepTheBitsAroundThem) {
    BitVector v = BitVector::from_string("10110");
    v.insert(2, 3, true);
    EXPECT_EQ(v.to_string(), "10111110");
    v.insert(0, false);
    EXPECT_EQ(v.to_string(), "010111110");
    v.insert(v.size(), 2, true);  // at the end: appends
    EXPECT_EQ(v.to_string(), "01011111011");
    v.erase(1, 7);
    EXPECT_EQ(v.to_string(), "01011");
    v.erase(0);
    EXPECT_EQ(v.to_string(), "1011");
    static_assert(!inserts_an_int<BitVector>, "insert(pos, 5) would insert one bit: it must not compile");
}

TEST(BitVector, SetBitsOfATemporaryOwnTheBits) {
    // The range of a temporary keeps the vector alive: under AddressSanitizer, a range over
    // the freed words of (a & b) is a heap-use-after-free.
    std::mt19937_64 rng(grape::testing::test_seed(15));
    const Model ma = random_model(rng, 5000, 0.5), mb = random_model(rng, 5000, 0.5);
    const BitVector a = from_model(ma), b = from_model(mb);
    std::vector<std::size_t> expected;
    for (std::size_t i = 0; i < 5000; ++i)
        if (ma[i] && mb[i]) expected.push_back(i);
    std::vector<std::size_t> got;
    for (std::size_t i : (a & b).set_bits()) {
        std::vector<std::size_t> churn(64, i);  // allocations that would reuse freed memory
        got.push_back(churn.back());
    }
    EXPECT_EQ(got, expected);
    got.clear();
    const auto make_const = [&]() -> const BitVector { return a & b; };
    for (std::size_t i : make_const().set_bits()) got.push_back(i);
    EXPECT_EQ(got, expected);
    static_assert(std::same_as<decltype(a.set_bits()), BitVector::SetBits>);
    static_assert(std::same_as<decltype((a & b).set_bits()), BitVector::OwnedSetBits>);
    static_assert(std::same_as<decltype(make_const().set_bits()), BitVector::OwnedSetBits>);
    static_assert(std::ranges::forward_range<BitVector::OwnedSetBits>);
    EXPECT_EQ(distance_of(BitVector::from_string("0101").set_bits()), 2);
}

TEST(BitVector, MoveLeavesTheSourceEmpty) {
    BitVector a(100, true);
    BitVector b(std::move(a));
    EXPECT_EQ(a.size(), 0u);  // NOLINT(bugprone-use-after-move): the moved-from state is specified
    EXPECT_TRUE(a.words().empty());
    EXPECT_EQ(b.count(), 100u);
    BitVector c(3);
    c = std::move(b);
    EXPECT_EQ(b.size(), 0u);  // NOLINT(bugprone-use-after-move)
    EXPECT_EQ(c.count(), 100u);
    BitVector& self = c;
    c = std::move(self);
    EXPECT_EQ(c.count(), 100u);
}

TEST(BitVector, ReferenceProxyAssignsThroughTheIndex) {
    BitVector v(70);
    v[3] = true;
    v[69] = true;
    v[4] = v[3];   // copies the value, does not rebind
    v[3] = false;
    EXPECT_EQ(v.to_string(), "0000100000000000000000000000000000000000000000000000000000000000000001");
    auto r = v[69];
    r.flip();
    EXPECT_FALSE(v.get(69));
    const BitVector& cv = v;
    static_assert(std::same_as<decltype(cv[0]), bool>);
    static_assert(std::same_as<decltype(v[0]), BitVector::Reference>);
    bool read = v[4];
    EXPECT_TRUE(read);
}

TEST(BitVector, OrderKeysAMapAndIsTheDocumentedOne) {
    // Shorter first; at equal sizes the highest differing bit decides.
    EXPECT_LT(BitVector(3, true), BitVector(4));
    EXPECT_LT(BitVector::from_string("1110"), BitVector::from_string("0001"));  // 7 < 8
    // Strings built by append: g++ 12 at -O3 misreads "literal" + std::string as an overlapping copy.
    const auto bits = [](std::string a, char fill, std::size_t n, const char* b) { return a.append(n, fill).append(b); };
    EXPECT_LT(BitVector::from_string(bits("", '1', 64, "0")), BitVector::from_string(bits("", '0', 64, "1")));
    EXPECT_LT(BitVector::from_string(bits("1", '0', 63, "1")), BitVector::from_string(bits("0", '1', 64, "")));
    EXPECT_FALSE(BitVector(5) < BitVector(5));
    // All vectors of sizes 0-3 in one map: 1 + 2 + 4 + 8 = 15 distinct keys in the model's order.
    std::map<BitVector, int> map;
    std::vector<Model> all;
    for (std::size_t size = 0; size <= 3; ++size)
        for (unsigned code = 0; code < (1u << size); ++code) {
            Model m(size);
            for (std::size_t i = 0; i < size; ++i) m[i] = (code >> i) & 1u;
            all.push_back(m);
        }
    std::mt19937_64 rng(grape::testing::test_seed(4));
    for (int t = 0; t < 200; ++t) ++map[from_model(all[rng() % all.size()])];
    std::vector<Model> sorted = all;
    std::sort(sorted.begin(), sorted.end(), model_less);
    std::size_t k = 0, total = 0;
    for (const auto& [key, hits] : map) {
        while (k < sorted.size() && from_model(sorted[k]) != key) ++k;  // map keys in the model's order
        ASSERT_LT(k, sorted.size());
        total += static_cast<std::size_t>(hits);
    }
    EXPECT_EQ(total, 200u);
}

TEST(BitVector, ConvertsToAndFromStandardContainers) {
    std::mt19937_64 rng(grape::testing::test_seed(8));
    for (std::size_t n : boundary_sizes) {
        const Model m = random_model(rng, n, 0.5);
        const BitVector v = BitVector::from_bools(m);
        expect_matches(v, m);
        EXPECT_EQ(v.to_bools(), m);
    }
    std::bitset<129> b;
    b.set(0);
    b.set(64);
    b.set(128);
    const BitVector v = BitVector::from_bitset(b);
    EXPECT_EQ(v.size(), 129u);
    EXPECT_EQ(v.count(), 3u);
    EXPECT_TRUE(v.get(128));
    EXPECT_EQ(v.to_bitset<129>(), b);
    EXPECT_EQ(BitVector::from_bitset(std::bitset<0>()).size(), 0u);
    EXPECT_EQ((BitVector(64, true).to_bitset<64>()), std::bitset<64>().set());
    expect_error([&] { (void)v.to_bitset<128>(); }, {"to_bitset", "std::bitset<128>", "129 bits"});
}

// ---- binary form ----

std::vector<std::byte> bytes_of(std::initializer_list<int> values) {
    std::vector<std::byte> out;
    for (int x : values) out.push_back(static_cast<std::byte>(x));
    return out;
}

TEST(BitVector, BinaryFormIsTheDocumentedLittleEndianLayout) {
    BitVector v(65);
    v.set(0);
    v.set(9);
    v.set(63);
    v.set(64);
    // "GRBV", version 1, n = 65, word 0 = 2^63 + 2^9 + 1, word 1 = 1: all little-endian.
    const auto expected = bytes_of({'G', 'R', 'B', 'V', 1, 0, 0, 0, 65, 0, 0, 0, 0, 0, 0, 0,
                                    0x01, 0x02, 0, 0, 0, 0, 0, 0x80, 1, 0, 0, 0, 0, 0, 0, 0});
    EXPECT_EQ(v.to_bytes(), expected);
    EXPECT_EQ(BitVector::from_bytes(expected), v);
    EXPECT_EQ(BitVector().to_bytes().size(), 16u);
    std::mt19937_64 rng(grape::testing::test_seed(21));
    std::stringstream stream(std::ios::in | std::ios::out | std::ios::binary);
    std::vector<BitVector> saved;
    for (std::size_t n : edge_sizes) {
        const BitVector w = from_model(random_model(rng, n, 0.5));
        EXPECT_EQ(w.to_bytes().size(), 16 + 8 * ((n + 63) / 64));
        EXPECT_EQ(BitVector::from_bytes(w.to_bytes()), w);
        w.save(stream);
        saved.push_back(w);
    }
    BitVector big(300'000);  // more than one chunk of the stream code
    big.set_range(1000, 299'999);
    big.save(stream);
    saved.push_back(big);
    for (const BitVector& w : saved) EXPECT_EQ(BitVector::load(stream), w);  // back to back
    EXPECT_EQ(stream.peek(), std::char_traits<char>::eof());
}

TEST(BitVector, BinaryFormIsCheckedOnLoad) {
    const auto good = BitVector::from_string("1011").to_bytes();  // 24 bytes
    auto with = [&](std::size_t at, int value) {
        auto b = good;
        b[at] = static_cast<std::byte>(value);
        return b;
    };
    auto load_stream = [](const std::vector<std::byte>& b) {
        std::stringstream s(std::string(reinterpret_cast<const char*>(b.data()), b.size()));
        return BitVector::load(s);
    };
    expect_error([&] { (void)BitVector::from_bytes(std::span(good).first(15)); }, {"from_bytes", "15 bytes", "16-byte header"});
    expect_error([&] { (void)BitVector::from_bytes(with(0, 'X')); }, {"from_bytes", "not a bit vector", "GRBV"});
    expect_error([&] { (void)BitVector::from_bytes(with(4, 2)); }, {"format version 2", "expected 1"});
    expect_error([&] { (void)BitVector::from_bytes(with(8, 65)); }, {"24 bytes", "expected 32 for 65 bits"});
    auto longer = good;
    longer.push_back(std::byte{0});
    expect_error([&] { (void)BitVector::from_bytes(longer); }, {"25 bytes", "expected 24 for 4 bits"});
    expect_error([&] { (void)BitVector::from_bytes(with(16, 0x1D)); }, {"bits past the size (4)", "set"});
    expect_error([&] { (void)BitVector::from_bytes(with(23, 0x80)); }, {"bits past the size"});
    auto huge = good;  // n = 2^64 − 1
    for (std::size_t k = 8; k < 16; ++k) huge[k] = std::byte{0xFF};
    expect_error([&] { (void)BitVector::from_bytes(huge); }, {"size 18446744073709551615 bits is too large"});
    // Streams: the same checks, and a stream that ends early names the bytes it had.
    EXPECT_EQ(load_stream(good), BitVector::from_string("1011"));
    expect_error([&] { (void)load_stream(std::vector(good.begin(), good.begin() + 10)); }, {"load", "after 10 bytes", "header"});
    expect_error([&] { (void)load_stream(std::vector(good.begin(), good.begin() + 20)); }, {"load", "after 20 bytes", "expected 24 for 4 bits"});
    expect_error([&] { (void)load_stream(with(16, 0xF1)); }, {"load", "bits past the size"});
    expect_error([&] { (void)load_stream(with(5, 1)); }, {"load", "format version 257"});
    auto claims_a_lot = good;  // n = 2^40 bits (128 GiB) with 8 bytes behind: fails, allocates little
    claims_a_lot[13] = std::byte{1};
    claims_a_lot[8] = std::byte{0};
    expect_error([&] { (void)load_stream(claims_a_lot); }, {"after 24 bytes", "for 1099511627776 bits"});
    std::ostringstream broken;
    broken.setstate(std::ios::badbit);
    expect_error([&] { BitVector(10).save(broken); }, {"save", "stream failed"});
}

// The shift and rank kernels of every instruction-set version against bit-by-bit models.
TEST(BitVector, EveryKernelVersionShiftsAndFindsRanks) {
    std::size_t versions = 0;
    const grape::detail::WordKernels* const* list = grape::detail::runnable_word_kernels(versions);
    std::mt19937_64 rng(grape::testing::test_seed(6));
    for (std::size_t k = 0; k < versions; ++k) {
        const auto& kern = *list[k];
        SCOPED_TRACE(kern.name);
        for (std::size_t n = 0; n < 40; n += (n < 20 ? 1 : 9)) {
            std::vector<std::uint64_t> a(n);
            for (auto& w : a) w = rng() & rng();  // density 1/4
            auto bit = [](const std::vector<std::uint64_t>& w, std::size_t i) { return (w[i / 64] >> (i % 64)) & 1u; };
            for (std::size_t s : {0u, 1u, 5u, 63u, 64u, 65u, 127u, 128u, 200u, 1000u, 2600u}) {
                std::vector<std::uint64_t> up = a, down = a;
                kern.shift_up(up.data(), n, s);
                kern.shift_down(down.data(), n, s);
                for (std::size_t i = 0; i < 64 * n; ++i) {
                    ASSERT_EQ(bit(up, i), i >= s ? bit(a, i - s) : 0u) << "up " << s << " bit " << i;
                    ASSERT_EQ(bit(down, i), s < 64 * n - i ? bit(a, i + s) : 0u) << "down " << s << " bit " << i;
                }
            }
            std::size_t ones = 0;
            for (auto w : a) ones += static_cast<std::size_t>(std::popcount(w));
            for (std::size_t r = 0; r <= ones + 1; ++r) {
                std::size_t before = 12345, seen = 0, word = 0;
                while (word < n && seen + static_cast<std::size_t>(std::popcount(a[word])) <= r)
                    seen += static_cast<std::size_t>(std::popcount(a[word++]));
                ASSERT_EQ(kern.find_rank(a.data(), n, r, before), word) << "rank " << r;
                ASSERT_EQ(before, seen);
            }
        }
    }
}

// ---- PairBits: index back to the pair, and the walk over set pairs ----

TEST(PairBits, PairIsTheInverseOfIndex) {
    for (std::size_t n = 0; n <= 100; ++n) {
        const PairBits pairs(n);
        for (std::size_t k = 0; k < pairs.pair_count(); ++k) {
            const auto [i, j] = pairs.pair(k);
            ASSERT_LT(i, j);
            ASSERT_LT(j, n);
            ASSERT_EQ(pairs.index(i, j), k) << "n " << n << " index " << k;
        }
    }
    // A large n (199,990,000 pairs): every row's first and last pair, and random pairs.
    const std::size_t n = 20'000;
    const PairBits big(n);
    for (std::size_t i = 0; i + 1 < n; i += (i < 50 || i > n - 50 ? 1 : 997)) {
        ASSERT_EQ(big.pair(big.index(i, i + 1)), std::make_pair(i, i + 1));
        ASSERT_EQ(big.pair(big.index(i, n - 1)), std::make_pair(i, n - 1));
    }
    std::mt19937_64 rng(grape::testing::test_seed(17));
    for (int t = 0; t < 10'000; ++t) {
        const std::size_t i = rng() % n, j = rng() % n;
        if (i == j) continue;
        ASSERT_EQ(big.pair(big.index(i, j)), std::make_pair(std::min(i, j), std::max(i, j)));
    }
    expect_error([&] { (void)big.pair(big.pair_count()); }, {"PairBits::pair", "index 199990000", "pair_count 199990000"});
    expect_error([] { (void)PairBits(1).pair(0); }, {"index 0", "pair_count 0"});
}

template <class P>
concept walks_a_temporary = requires { P(5).set_pairs(); };

TEST(PairBits, SetPairsWalkInIndexOrder) {
    std::mt19937_64 rng(grape::testing::test_seed(19));
    for (std::size_t n : {0u, 1u, 2u, 3u, 12u, 64u, 65u, 150u}) {
        PairBits pairs(n);
        std::vector<std::pair<std::size_t, std::size_t>> expected;
        for (std::size_t i = 0; i < n; ++i)
            for (std::size_t j = i + 1; j < n; ++j)
                if (rng() % 5 == 0 || (i == 0 && j == 1) || (i + 2 == n && j + 1 == n)) {  // with both ends
                    pairs.set(j, i);
                    expected.emplace_back(i, j);
                }
        std::vector<std::pair<std::size_t, std::size_t>> walked, called;
        for (auto [i, j] : pairs.set_pairs()) walked.emplace_back(i, j);
        pairs.for_each_set([&](std::size_t i, std::size_t j) { called.emplace_back(i, j); });
        EXPECT_EQ(walked, expected) << "n " << n;
        EXPECT_EQ(called, expected) << "n " << n;
    }
    static_assert(std::ranges::forward_range<PairBits::SetPairs>);
    static_assert(!walks_a_temporary<PairBits>, "a range over a temporary's bits must not compile");
}

// ---- KeyState: key types, the frame's lists, key repeat ----

enum ScancodeLike { scan_a = 4, scan_s = 22, scan_lctrl = 224 };           // as SDL_Scancode
enum KeycodeLike : std::int32_t { key_a = 'a', key_right = 0x4000004F };  // as SDL_Keycode values
enum class Action : unsigned char { jump = 3, fire = 7 };
enum class Signed : short { minus = -1 };

TEST(KeyState, AcceptsAnyIntegerOrEnumKeyType) {
    KeyState keys(256);
    const int ctrl = 224, s = 22;  // int variables: no narrowing error in the braces
    const BitVector save = keys.mask({ctrl, s});
    EXPECT_EQ(save, keys.mask({scan_lctrl, scan_s}));
    EXPECT_EQ(save, keys.mask(scan_lctrl, 22u));  // mixed types
    EXPECT_EQ(save, keys.mask({std::size_t{224}, std::size_t{22}}));
    EXPECT_EQ(keys.mask({Action::jump, Action::fire}).to_string().substr(0, 8), "00010001");
    EXPECT_EQ(keys.mask({key_a}).find_first(), 97u);
    EXPECT_EQ(keys.mask({static_cast<unsigned char>(200)}).find_first(), 200u);
    keys.press(scan_lctrl);
    keys.press(Action::jump);
    keys.press(key_a);
    keys.press(static_cast<std::uint16_t>(22));
    EXPECT_TRUE(keys.all_down(save));
    EXPECT_TRUE(keys.is_down(Action::jump));
    EXPECT_TRUE(keys.is_down(97L));
    EXPECT_FALSE(keys.is_down(key_right));      // beyond key_count: never down
    EXPECT_FALSE(keys.is_down(Signed::minus));  // negative: never down
    EXPECT_FALSE(keys.pressed_this_frame(-5));
    keys.release(Action::jump);
    EXPECT_TRUE(keys.released_this_frame(Action::jump));
    expect_error([&] { (void)keys.mask({-1}); }, {"KeyState::mask", "key -1", "key_count 256"});
    expect_error([&] { (void)keys.mask({key_right}); }, {"key 1073741903", "out of range"});
    expect_error([&] { keys.press(Signed::minus); }, {"KeyState::press", "key -1"});
    expect_error([&] { keys.release(256u); }, {"KeyState::release", "key 256"});
    expect_error([&] { keys.press(std::numeric_limits<std::uint64_t>::max()); }, {"key 18446744073709551615"});
}

TEST(KeyState, ListsTheFramesEdgesInOrder) {
    KeyState keys;
    keys.press(7);
    keys.press(300);
    keys.press(7);    // held: not a new press
    keys.release(300);
    keys.press(300);  // tapped again: still listed once
    keys.press(2);
    using List = std::vector<std::size_t>;
    auto list = [](std::span<const std::size_t> s) { return List(s.begin(), s.end()); };
    EXPECT_EQ(list(keys.pressed_keys()), (List{7, 300, 2}));
    EXPECT_EQ(list(keys.released_keys()), (List{300}));
    keys.end_frame();
    EXPECT_TRUE(keys.pressed_keys().empty());
    EXPECT_TRUE(keys.released_keys().empty());
    for (std::size_t k : {2u, 7u, 300u}) EXPECT_FALSE(keys.pressed_this_frame(k) || keys.released_this_frame(k));
    keys.release(2);
    keys.release_all();  // 7 and 300 still down: released in the order they were pressed
    EXPECT_EQ(list(keys.released_keys()), (List{2, 7, 300}));
    EXPECT_TRUE(keys.down().none());
}

TEST(KeyState, RepeatsAtTheDelayAndIntervalAsTheFramesSeeThem) {
    // delay 1/2 s, interval 1/4 s, frames of 1/8 s: the key pressed in frame 0 (time 0) repeats
    // at 0.5, 0.75, 1.0, … which are the clock readings of frames 4, 6, 8.
    KeyState keys(64, {.delay = 0.5, .interval = 0.25});
    std::vector<int> repeated_frames;
    for (int frame = 0; frame <= 8; ++frame) {
        EXPECT_EQ(keys.time(), frame * 0.125);
        if (frame == 0) keys.press(5);
        if (frame == 3) keys.press(5);  // an OS repeat of a held key: does not restart the delay
        if (frame == 8) keys.release(5);
        if (keys.repeated_this_frame(5)) {
            repeated_frames.push_back(frame);
            EXPECT_EQ(keys.repeat_count(5), 1u);
            EXPECT_TRUE(keys.pressed_or_repeated(5));
        }
        EXPECT_EQ(keys.pressed_or_repeated(5), frame == 0 || keys.repeated_this_frame(5));
        keys.end_frame(0.125);
    }
    EXPECT_EQ(repeated_frames, (std::vector<int>{4, 6, 8}));  // 8: due at 1.0, before the release
    EXPECT_FALSE(keys.repeated_this_frame(5));                 // released: no more repeats
    // A long frame holds several repeats: pressed at 9/8, due at 13/8, 15/8, … 25/8.
    keys.press(9);
    keys.end_frame(2.0);
    EXPECT_EQ(keys.repeat_count(9), 7u);
    EXPECT_EQ(keys.repeated_keys().size(), 1u);
    keys.end_frame();  // no time passes: no repeats
    EXPECT_EQ(keys.repeat_count(9), 0u);
    EXPECT_TRUE(keys.repeated_keys().empty());
    EXPECT_EQ(keys.time(), 3.125);
    expect_error([] { KeyState bad(8, {.delay = 0}); }, {"repeat.delay", "> 0", "got 0"});
    expect_error([] { KeyState bad(8, {.interval = std::nan("")}); }, {"repeat.interval", "got nan"});
    expect_error([&] { keys.end_frame(-0.125); }, {"end_frame", "dt", "got -0.125"});
    expect_error([&] { keys.end_frame(INFINITY); }, {"end_frame", "got inf"});
}

// Random presses, releases and frame lengths against a model that counts in ticks of 1/16 s
// and lists each repeat time one by one (delay 5 ticks, interval 2 ticks: dyadic, so exact).
TEST(KeyState, RepeatsMatchATickModelOverRandomFrames) {
    constexpr std::size_t key_count = 8;
    constexpr long delay = 5, interval = 2;
    KeyState keys(key_count, {.delay = delay / 16.0, .interval = interval / 16.0});
    std::mt19937_64 rng(grape::testing::test_seed(1515));
    std::vector<bool> down(key_count);
    std::vector<long> since(key_count);
    std::vector<std::size_t> held;  // keys down, in press order
    std::vector<std::size_t> repeat_counts(key_count), repeat_order;
    long now = 0;
    for (int frame = 0; frame < 3000; ++frame) {
        // Events of this frame.
        std::vector<std::size_t> pressed, released;
        const int events = static_cast<int>(rng() % 4);
        for (int e = 0; e < events; ++e) {
            const std::size_t k = rng() % key_count;
            if (rng() % 2 == 0) {
                keys.press(k);
                if (!down[k]) {
                    down[k] = true;
                    since[k] = now;
                    held.push_back(k);
                    if (std::find(pressed.begin(), pressed.end(), k) == pressed.end()) pressed.push_back(k);
                }
            } else {
                keys.release(k);
                if (down[k]) {
                    down[k] = false;
                    held.erase(std::find(held.begin(), held.end(), k));
                    if (std::find(released.begin(), released.end(), k) == released.end()) released.push_back(k);
                }
            }
        }
        for (std::size_t k = 0; k < key_count; ++k) {
            ASSERT_EQ(keys.is_down(k), static_cast<bool>(down[k])) << "frame " << frame;
            ASSERT_EQ(keys.repeat_count(k), repeat_counts[k]) << "frame " << frame << " key " << k;
            ASSERT_EQ(keys.repeated_this_frame(k), repeat_counts[k] > 0);
        }
        ASSERT_EQ(std::vector<std::size_t>(keys.pressed_keys().begin(), keys.pressed_keys().end()), pressed);
        ASSERT_EQ(std::vector<std::size_t>(keys.released_keys().begin(), keys.released_keys().end()), released);
        ASSERT_EQ(std::vector<std::size_t>(keys.repeated_keys().begin(), keys.repeated_keys().end()), repeat_order);
        // The frame ends after 0 to 12 ticks (long frames see several repeats).
        const long ticks = static_cast<long>(rng() % 13);
        std::fill(repeat_counts.begin(), repeat_counts.end(), 0);
        repeat_order.clear();
        for (const std::size_t k : held) {
            for (long due = since[k] + delay; due <= now + ticks; due += interval)
                if (due > now) ++repeat_counts[k];
            if (repeat_counts[k] > 0) repeat_order.push_back(k);
        }
        keys.end_frame(static_cast<double>(ticks) / 16.0);
        now += ticks;
    }
}


// ---- SparseBitVector: against the model, across the array/bitmap limit ----

// Blocks whose model count exceeds the array limit: those must be bitmaps (canonical form).
std::size_t model_bitmap_blocks(const Model& m) {
    std::size_t blocks = 0;
    for (std::size_t first = 0; first < m.size(); first += SparseBitVector::block_bits)
        blocks += model_count(m, first, std::min(m.size(), first + SparseBitVector::block_bits)) > SparseBitVector::array_limit;
    return blocks;
}

void expect_sparse_matches(const SparseBitVector& v, const Model& m) {
    ASSERT_EQ(v.size(), m.size());
    std::vector<std::size_t> expected, walked;
    for (std::size_t i = 0; i < m.size(); ++i)
        if (m[i]) expected.push_back(i);
    v.for_each_set([&](std::size_t i) { walked.push_back(i); });
    ASSERT_EQ(walked, expected);
    EXPECT_EQ(v.count(), expected.size());
    EXPECT_EQ(v.any(), !expected.empty());
    // `&=` may leave sparse results as bitmaps; shrink_to_fit() gives the canonical form.
    EXPECT_GE(v.bitmap_blocks(), model_bitmap_blocks(m));
    SparseBitVector fitted = v;
    fitted.shrink_to_fit();
    EXPECT_EQ(fitted.bitmap_blocks(), model_bitmap_blocks(m));
    EXPECT_EQ(fitted, v);
    EXPECT_EQ(fitted.count(), expected.size());
    EXPECT_EQ(v.to_bits(), BitVector::from_bools(m));
    for (std::size_t k = 0; k < 50 && !m.empty(); ++k) {
        const std::size_t i = (k * 7919 + 13) % m.size();
        ASSERT_EQ(v.get(i), static_cast<bool>(m[i])) << "bit " << i;
    }
}

// A model with bits clustered in one random block (dense enough to pass the array limit)
// plus a thin sprinkle elsewhere.
Model clustered_model(std::mt19937_64& rng, std::size_t size) {
    Model m(size);
    if (size == 0) return m;
    const double dense = std::uniform_real_distribution<double>(0.0, 0.15)(rng), thin = 0.002;
    const std::size_t hot = rng() % (size / SparseBitVector::block_bits + 1);
    std::bernoulli_distribution in_hot(dense), elsewhere(thin);
    for (std::size_t i = 0; i < size; ++i) m[i] = i / SparseBitVector::block_bits == hot ? in_hot(rng) : elsewhere(rng);
    return m;
}

TEST(SparseBitVector, RandomOperationsMatchVectorOfBool) {
    using grape::SparseBitVector;
    std::mt19937_64 rng(grape::testing::test_seed(20261217));
    const std::size_t sizes[] = {0, 1, 65535, 65536, 65537, 140000};
    for (int trial = 0; trial < 12; ++trial) {
        const std::size_t n = sizes[trial % 6];
        Model m = clustered_model(rng, n);
        SparseBitVector v = SparseBitVector::from_bits(BitVector::from_bools(m));
        expect_sparse_matches(v, m);
        for (int op = 0; op < 24 && n > 0; ++op) {
            SCOPED_TRACE("trial " + std::to_string(trial) + " op " + std::to_string(op));
            switch (rng() % 5) {
                case 0: {  // a burst of sets or clears in one block: crosses the array limit either way
                    const std::size_t base = (rng() % (n / SparseBitVector::block_bits + 1)) * SparseBitVector::block_bits;
                    const bool value = rng() % 2 == 0;
                    for (int k = 0; k < 3000; ++k) {
                        const std::size_t i = std::min(n - 1, base + rng() % SparseBitVector::block_bits);
                        if (k % 2 == 0) {
                            v.set(i, value);
                            m[i] = value;
                        } else {
                            EXPECT_EQ(v.test_and_set(i), static_cast<bool>(m[i]));
                            m[i] = true;
                        }
                    }
                    break;
                }
                case 1: case 2: {
                    const Model o = clustered_model(rng, n);
                    const SparseBitVector ov = SparseBitVector::from_bits(BitVector::from_bools(o));
                    const bool is_and = rng() % 2 == 0;
                    if (is_and) v &= ov; else v |= ov;
                    for (std::size_t i = 0; i < n; ++i) m[i] = is_and ? (m[i] && o[i]) : (m[i] || o[i]);
                    break;
                }
                case 3: {
                    const std::size_t i = rng() % n;
                    v.reset(i);
                    m[i] = false;
                    const SparseBitVector& same = v;
                    v &= same;
                    v |= same;
                    break;
                }
                default:
                    if (rng() % 4 == 0) {
                        v.clear_all();
                        m.assign(n, false);
                    }
                    break;
            }
            expect_sparse_matches(v, m);
            EXPECT_EQ(v, SparseBitVector::from_bits(BitVector::from_bools(m)));  // the same bits, whatever the forms
            if (HasFatalFailure()) return;
        }
    }
}

TEST(SparseBitVector, StoresSparseBitsCompactly) {
    using grape::SparseBitVector;
    SparseBitVector v(10'000'000);
    for (std::size_t i = 0; i < 10'000'000; i += 1000) v.set(i);  // density 1/1000
    EXPECT_EQ(v.count(), 10'000u);
    EXPECT_EQ(v.bitmap_blocks(), 0u);
    // 2 bytes per set bit plus one record per block (153 blocks), far below the 1.25 MB of a
    // BitVector; growth by insertion may leave each array up to twice its size until
    // shrink_to_fit().
    const std::size_t table = 153 * sizeof(std::vector<int>) * 3;  // a record is at most 3 vectors wide
    EXPECT_LE(v.memory_bytes(), 2 * 2 * 10'000 + table);
    v.shrink_to_fit();
    EXPECT_LE(v.memory_bytes(), 2 * 10'000 + table);
    EXPECT_EQ(v.count(), 10'000u);
    SparseBitVector w(10'000'000);
    expect_error([&] { v &= SparseBitVector(5); }, {"SparseBitVector::operator&=", "size 5", "(10000000)"});
    expect_error([&] { v |= SparseBitVector(5); }, {"SparseBitVector::operator|="});
    v &= w;
    EXPECT_FALSE(v.any());
    EXPECT_EQ(v, w);
}

// Dense `&=` is a plain and; the block's count and form follow when needed.
TEST(SparseBitVector, DenseAndCountsLaterAndKeepsTheBits) {
    using grape::SparseBitVector;
    const std::size_t n = 3 * SparseBitVector::block_bits;
    BitVector thirds(n), halves(n), odd(n);
    for (std::size_t i = 0; i < n; i += 3) thirds.set(i);  // ~21,845 per block: bitmaps
    for (std::size_t i = 0; i < n; i += 2) halves.set(i);
    for (std::size_t i = 1; i < n; i += 2) odd.set(i);
    for (std::size_t i = 0; i < n; i += 3) odd.reset(i);  // nothing in common with thirds

    SparseBitVector x = SparseBitVector::from_bits(thirds);
    x &= SparseBitVector::from_bits(halves);  // every sixth bit: still over the array limit
    const BitVector sixth = thirds & halves;
    EXPECT_EQ(x.count(), sixth.count());
    EXPECT_EQ(x.to_bits(), sixth);
    EXPECT_EQ(x, SparseBitVector::from_bits(sixth));
    x.set(1);    // a set and a clear on an uncounted bitmap
    x.reset(0);
    BitVector expected = sixth;
    expected.set(1);
    expected.reset(0);
    EXPECT_EQ(x.count(), expected.count());
    EXPECT_EQ(x.to_bits(), expected);

    SparseBitVector none = SparseBitVector::from_bits(thirds);
    none &= SparseBitVector::from_bits(odd);  // two bitmaps with no bit in common
    EXPECT_FALSE(none.any());
    EXPECT_EQ(none.count(), 0u);
    EXPECT_EQ(none, SparseBitVector(n));      // the same bits as empty blocks
    EXPECT_EQ(none.bitmap_blocks(), 3u);      // still bitmaps ...
    none.shrink_to_fit();
    EXPECT_EQ(none.bitmap_blocks(), 0u);      // ... until shrink_to_fit()
    EXPECT_EQ(none.memory_bytes(), SparseBitVector(n).memory_bytes());
    EXPECT_NE(x, none);
}

TEST(SparsePairBits, MatchesPairBitsAndScalesToManyObjects) {
    using grape::SparsePairBits;
    std::mt19937_64 rng(grape::testing::test_seed(23));
    // Against PairBits itself on 300 objects, then random pairs of 100,000 objects (4,999,950,000
    // pairs: 625 MB as a PairBits) against a sorted model.
    PairBits dense(300);
    SparsePairBits sparse(300);
    for (int t = 0; t < 5000; ++t) {
        const std::size_t i = rng() % 300, j = rng() % 300;
        if (i == j) continue;
        ASSERT_EQ(sparse.test_and_set(i, j), dense.test_and_set(j, i));
        ASSERT_EQ(sparse.index(i, j), dense.index(i, j));
    }
    std::vector<std::pair<std::size_t, std::size_t>> a, b;
    dense.for_each_set([&](std::size_t i, std::size_t j) { a.emplace_back(i, j); });
    sparse.for_each_set([&](std::size_t i, std::size_t j) { b.emplace_back(i, j); });
    EXPECT_EQ(a, b);
    EXPECT_EQ(sparse.bits().to_bits(), dense.bits());
    EXPECT_EQ(sparse.pair(sparse.index(17, 4)), std::make_pair(std::size_t{4}, std::size_t{17}));

    SparsePairBits many(100'000);
    EXPECT_EQ(many.pair_count(), 4'999'950'000u);
    std::vector<std::pair<std::size_t, std::size_t>> model;
    for (int t = 0; t < 3000; ++t) {
        std::size_t i = rng() % 100'000, j = rng() % 100'000;
        if (i == j) continue;
        if (i > j) std::swap(i, j);
        many.set(j, i);
        model.emplace_back(i, j);
    }
    many.set(99'998, 99'999);  // the last pair
    model.emplace_back(99'998, 99'999);
    std::sort(model.begin(), model.end());
    model.erase(std::unique(model.begin(), model.end()), model.end());
    std::vector<std::pair<std::size_t, std::size_t>> walked;
    many.for_each_set([&](std::size_t i, std::size_t j) { walked.emplace_back(i, j); });
    EXPECT_EQ(walked, model);
    EXPECT_EQ(many.bits().count(), model.size());
    EXPECT_TRUE(many.test(99'999, 99'998));
    EXPECT_LT(many.bits().memory_bytes(), 8'000'000u);  // the block table (76,295 records) and the arrays
    expect_error([&] { (void)many.index(5, 5); }, {"SparsePairBits", "both 5"});
    expect_error([&] { many.set(0, 100'000); }, {"SparsePairBits", "index 100000", "object_count 100000"});
    expect_error([&] { (void)many.pair(many.pair_count()); }, {"SparsePairBits::pair", "pair_count 4999950000"});
    many.clear_all();
    EXPECT_FALSE(many.bits().any());
}

}  // namespace
