// Bits for JavaScript: BitVector (checked indices), PairBits and KeyState.
#include "web_util.hpp"

#include <grape/bits.hpp>

#include <emscripten/bind.h>

#include <cmath>
#include <string>

namespace grape::web {
namespace {

void check(const BitVector& b, unsigned i, const char* operation) {
    if (i >= b.size())
        throw Error(std::string("BitVector.") + operation + ": index " + std::to_string(i) + " is not below the size " +
                    std::to_string(b.size()));
}

BitVector* make_bits(unsigned size, bool value) {
    std::string message;
    try {
        return new BitVector(size, value);
    } catch (const std::exception& e) {
        message = e.what();
    }
    throw_js(message);
}
BitVector* make_clear_bits(unsigned size) { return make_bits(size, false); }
BitVector from_string(std::string bits) { return BitVector::from_string(bits); }
unsigned size(const BitVector& b) { return unsigned(b.size()); }
bool get(const BitVector& b, unsigned i) { return b.at(i); }
void set(BitVector& b, unsigned i, bool value) { check(b, i, "set"); b.set(i, value); }
void set_one(BitVector& b, unsigned i) { set(b, i, true); }
void flip(BitVector& b, unsigned i) { check(b, i, "flip"); b.flip(i); }
bool test_and_set(BitVector& b, unsigned i) { check(b, i, "testAndSet"); return b.test_and_set(i); }
void and_with(BitVector& a, const BitVector& b) { a &= b; }
void or_with(BitVector& a, const BitVector& b) { a |= b; }
void xor_with(BitVector& a, const BitVector& b) { a ^= b; }
void subtract(BitVector& a, const BitVector& b) { a.subtract(b); }
BitVector and_of(const BitVector& a, const BitVector& b) { return a & b; }
BitVector or_of(const BitVector& a, const BitVector& b) { return a | b; }
BitVector xor_of(const BitVector& a, const BitVector& b) { return a ^ b; }
BitVector not_of(const BitVector& a) { return ~a; }
unsigned count(const BitVector& b) { return unsigned(b.count()); }
bool subset(const BitVector& a, const BitVector& b) { return a.is_subset_of(b); }
bool intersects(const BitVector& a, const BitVector& b) { return a.intersects(b); }
// -1 when there is none (npos).
double find_first(const BitVector& b) { const auto i = b.find_first(); return i == BitVector::npos ? -1.0 : double(i); }
double find_next(const BitVector& b, unsigned i) { const auto j = b.find_next(i); return j == BitVector::npos ? -1.0 : double(j); }
val set_bits(const BitVector& b) {
    val out = val::array();
    for (std::size_t i : b.set_bits()) out.call<void>("push", unsigned(i));
    return out;
}
void resize(BitVector& b, unsigned size, bool value) { b.resize(size, value); }
void resize_clear(BitVector& b, unsigned size) { b.resize(size); }
bool equals(const BitVector& a, const BitVector& b) { return a == b; }
std::string text(const BitVector& b) { return b.to_string(); }
BitVector copy(const BitVector& b) { return b; }

PairBits* make_pairs(unsigned n) {
    std::string message;
    try {
        return new PairBits(n);
    } catch (const std::exception& e) {
        message = e.what();
    }
    throw_js(message);
}
bool pair_test(const PairBits& p, unsigned i, unsigned j) { return p.test(i, j); }
void pair_set(PairBits& p, unsigned i, unsigned j, bool v) { p.set(i, j, v); }
void pair_set_one(PairBits& p, unsigned i, unsigned j) { p.set(i, j); }
bool pair_test_and_set(PairBits& p, unsigned i, unsigned j) { return p.test_and_set(i, j); }
unsigned pair_index(const PairBits& p, unsigned i, unsigned j) { return unsigned(p.index(i, j)); }
unsigned pair_count(const PairBits& p) { return unsigned(p.pair_count()); }
void pair_clear(PairBits& p) { p.clear_all(); }

KeyState* make_keys(unsigned n) {
    std::string message;
    try {
        return new KeyState(n);
    } catch (const std::exception& e) {
        message = e.what();
    }
    throw_js(message);
}
KeyState* make_default_keys() { return make_keys(KeyState::default_key_count); }
void press(KeyState& k, unsigned key) { k.press(key); }
void release(KeyState& k, unsigned key) { k.release(key); }
bool is_down(const KeyState& k, unsigned key) { return k.is_down(key); }
bool pressed(const KeyState& k, unsigned key) { return k.pressed_this_frame(key); }
bool released(const KeyState& k, unsigned key) { return k.released_this_frame(key); }
// Two overloads in C++ (end_frame() and end_frame(dt), which also gathers key repeats): two
// arities in JavaScript.
void end_frame(KeyState& k) { k.end_frame(); }
void end_frame_after(KeyState& k, double dt) { k.end_frame(dt); }
BitVector mask(const KeyState& k, val keys) {
    BitVector m(k.key_count());
    for (double key : numbers(keys)) {
        if (!(key >= 0.0) || key >= double(k.key_count()) || key != std::floor(key))
            throw Error("KeyState.mask: key " + detail::number_text(key) + " is not a code below " + std::to_string(k.key_count()));
        m.set(unsigned(key));
    }
    return m;
}
bool all_down(const KeyState& k, const BitVector& m) { return k.all_down(m); }
bool any_down(const KeyState& k, const BitVector& m) { return k.any_down(m); }
BitVector down(const KeyState& k) { return k.down(); }
unsigned key_count(const KeyState& k) { return unsigned(k.key_count()); }

}  // namespace

EMSCRIPTEN_BINDINGS(grape_bits) {
    using namespace emscripten;
    class_<BitVector>("BitVector")
        .constructor(&make_bits, allow_raw_pointers())
        .constructor(&make_clear_bits, allow_raw_pointers())
        .class_function("fromString", guarded<&from_string>)
        .function("size", &size)
        .function("get", guarded<&get>)
        .function("set", guarded<&set>)
        .function("set", guarded<&set_one>)
        .function("flip", guarded<&flip>)
        .function("testAndSet", guarded<&test_and_set>)
        .function("setAll", method<&BitVector::set_all>)
        .function("clearAll", method<&BitVector::clear_all>)
        .function("flipAll", method<&BitVector::flip_all>)
        .function("andWith", guarded<&and_with>)
        .function("orWith", guarded<&or_with>)
        .function("xorWith", guarded<&xor_with>)
        .function("subtract", guarded<&subtract>)
        .function("and", guarded<&and_of>)
        .function("or", guarded<&or_of>)
        .function("xor", guarded<&xor_of>)
        .function("not", guarded<&not_of>)
        .function("count", &count)
        .function("any", method<&BitVector::any>)
        .function("none", method<&BitVector::none>)
        .function("all", method<&BitVector::all>)
        .function("isSubsetOf", guarded<&subset>)
        .function("intersects", guarded<&intersects>)
        .function("findFirst", &find_first)
        .function("findNext", &find_next)
        .function("setBits", &set_bits)
        .function("resize", guarded<&resize>)
        .function("resize", guarded<&resize_clear>)
        .function("equals", &equals)
        .function("toString", guarded<&text>)
        .function("clone", guarded<&copy>);
    class_<PairBits>("PairBits")
        .constructor(&make_pairs, allow_raw_pointers())
        .function("test", guarded<&pair_test>)
        .function("set", guarded<&pair_set>)
        .function("set", guarded<&pair_set_one>)
        .function("testAndSet", guarded<&pair_test_and_set>)
        .function("index", guarded<&pair_index>)
        .function("pairCount", &pair_count)
        .function("clearAll", &pair_clear);
    class_<KeyState>("KeyState")
        .constructor(&make_keys, allow_raw_pointers())
        .constructor(&make_default_keys, allow_raw_pointers())
        .function("press", guarded<&press>)
        .function("release", guarded<&release>)
        .function("releaseAll", method<&KeyState::release_all>)
        .function("isDown", &is_down)
        .function("pressedThisFrame", &pressed)
        .function("releasedThisFrame", &released)
        .function("endFrame", &end_frame)
        .function("endFrame", guarded<&end_frame_after>)
        .function("mask", guarded<&mask>)
        .function("allDown", guarded<&all_down>)
        .function("anyDown", guarded<&any_down>)
        .function("down", guarded<&down>)
        .function("keyCount", &key_count);
}

}  // namespace grape::web
