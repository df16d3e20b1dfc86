// Reading JSON values at known pointers: every error names where it is and why.
#include "scene_json.hpp"

#include <grape/error.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace grape::scene_io {

[[noreturn]] void fail(const std::string& pointer, const std::string& why) {
    throw Error("scene: " + (pointer.empty() ? std::string("/") : pointer) + ": " + why);
}

// An object whose keys must all be among `allowed` (a typo such as "duraton" is an error,
// not a silently ignored field).
const json& object(const json& j, const std::string& pointer, std::initializer_list<std::string_view> allowed) {
    if (!j.is_object()) fail(pointer, "expected an object, got " + type_of(j));
    for (const auto& [key, value] : j.items()) {
        if (std::find(allowed.begin(), allowed.end(), key) == allowed.end()) {
            std::string list;
            for (std::string_view a : allowed) list += (list.empty() ? "" : ", ") + std::string(a);
            fail(child(pointer, key), "unknown field \"" + key + "\" (expected one of: " + list + ")");
        }
    }
    return j;
}

const json& required(const json& obj, const std::string& pointer, std::string_view key) {
    const auto it = obj.find(key);
    if (it == obj.end()) fail(pointer, "missing field \"" + std::string(key) + "\"");
    return *it;
}

double number(const json& j, const std::string& pointer) {
    if (!j.is_number()) fail(pointer, "expected a number, got " + type_of(j));
    const double v = j.get<double>();
    if (!std::isfinite(v)) fail(pointer, "number out of range");
    return v;
}

double number_field(const json& obj, const std::string& pointer, std::string_view key) {
    return number(required(obj, pointer, key), child(pointer, key));
}

double number_field(const json& obj, const std::string& pointer, std::string_view key, double fallback) {
    const auto it = obj.find(key);
    return it == obj.end() ? fallback : number(*it, child(pointer, key));
}

double positive_field(const json& obj, const std::string& pointer, std::string_view key) {
    const double v = number_field(obj, pointer, key);
    if (!(v > 0.0)) fail(child(pointer, key), "must be positive (got " + number_text(v) + ")");
    return v;
}

double non_negative_field(const json& obj, const std::string& pointer, std::string_view key, double fallback) {
    const double v = number_field(obj, pointer, key, fallback);
    if (v < 0.0) fail(child(pointer, key), "must not be negative (got " + number_text(v) + ")");
    return v;
}

bool bool_field(const json& obj, const std::string& pointer, std::string_view key, bool fallback) {
    return detail::bool_member(obj, pointer, key, fallback, fail);
}

std::string string_value(const json& j, const std::string& pointer) { return detail::string_of(j, pointer, fail); }

std::string string_field(const json& obj, const std::string& pointer, std::string_view key, std::string fallback) {
    const auto it = obj.find(key);
    return it == obj.end() ? fallback : string_value(*it, child(pointer, key));
}

int repeat_field(const json& obj, const std::string& pointer, int fallback) {
    const auto r = obj.find("repeat");
    if (r == obj.end()) return fallback;
    const long long repeat = integer(*r, child(pointer, "repeat"));
    if (repeat < -1 || repeat > 1000000000)
        fail(child(pointer, "repeat"), "must be −1 (forever) or a count in [0, 1e9] (got " + std::to_string(repeat) + ")");
    return static_cast<int>(repeat);
}

void curve_field(const json& obj, const std::string& pointer, const Scene& scene, Curve& curve, std::string& curve_name) {
    const auto c = obj.find("curve");
    if (c == obj.end()) return;
    const std::string text = string_value(*c, child(pointer, "curve"));
    if (const NamedCurve* named = scene.find_curve(text)) {
        curve = named->curve;
        curve_name = text;
        return;
    }
    try {
        curve = parse_curve(text);
    } catch (const Error& e) {
        fail(child(pointer, "curve"), std::string(e.what()) + " (nor is it a name in /curves)");
    }
}

long long integer(const json& j, const std::string& pointer) {
    const double v = number(j, pointer);
    if (v != std::floor(v) || std::abs(v) > 9e15) fail(pointer, "expected a whole number (got " + number_text(v) + ")");
    return static_cast<long long>(v);
}

Vec2 vec2(const json& j, const std::string& pointer) {
    if (!j.is_array() || j.size() != 2) fail(pointer, "expected a point [x, y], got " + type_of(j) + (j.is_array() ? " of " + std::to_string(j.size()) : ""));
    return {number(j[0], child(pointer, 0)), number(j[1], child(pointer, 1))};
}

Vec2 vec2_field(const json& obj, const std::string& pointer, std::string_view key) {
    return vec2(required(obj, pointer, key), child(pointer, key));
}

Vec2 vec2_field(const json& obj, const std::string& pointer, std::string_view key, Vec2 fallback) {
    const auto it = obj.find(key);
    return it == obj.end() ? fallback : vec2(*it, child(pointer, key));
}

const json& array_field(const json& obj, const std::string& pointer, std::string_view key) {
    const json& a = required(obj, pointer, key);
    if (!a.is_array()) fail(child(pointer, key), "expected an array, got " + type_of(a));
    return a;
}

std::vector<Vec2> points_field(const json& obj, const std::string& pointer, std::string_view key, std::size_t at_least) {
    const json& a = array_field(obj, pointer, key);
    const std::string p = child(pointer, key);
    if (a.size() < at_least)
        fail(p, "too few points: " + std::to_string(a.size()) + " (at least " + std::to_string(at_least) + ")");
    std::vector<Vec2> out;
    out.reserve(a.size());
    for (std::size_t i = 0; i < a.size(); ++i) out.push_back(vec2(a[i], child(p, i)));
    return out;
}


std::string name_field(const json& obj, const std::string& pointer, std::set<std::string>* unique) {
    const std::string name = string_field(obj, pointer, "name", "");
    if (unique) {
        if (name.empty()) fail(child(pointer, "name"), "must not be empty");
        if (!unique->insert(name).second) fail(child(pointer, "name"), "duplicate name \"" + name + "\"");
    }
    return name;
}

std::string one_of(const json& obj, const std::string& pointer, std::string_view key, std::string fallback,
                   const std::vector<std::string_view>& allowed) {
    const std::string v = string_field(obj, pointer, key, std::move(fallback));
    if (std::find(allowed.begin(), allowed.end(), v) == allowed.end()) {
        std::string list;
        for (auto a : allowed) list += (list.empty() ? "" : ", ") + std::string(a);
        fail(child(pointer, key), "unknown value \"" + v + "\" (" + list + ")");
    }
    return v;
}

std::size_t particle_index(const json& obj, const std::string& pointer, std::string_view key, std::size_t count) {
    const long long i = integer(required(obj, pointer, key), child(pointer, key));
    if (i < 0 || static_cast<std::size_t>(i) >= count)
        fail(child(pointer, key), "no particle " + std::to_string(i) + " (the simulation has " + std::to_string(count) + ")");
    return static_cast<std::size_t>(i);
}


namespace {

// Follows a SAX parse to the value being read, so that a number too large for a double
// (1e999) is reported at its JSON pointer, as every other bad value is.
class PointerTracker final : public nlohmann::json_sax<json> {
public:
    std::string pointer;  // of the value the parser refused
    std::string token;    // its text

    bool null() override { return value(); }
    bool boolean(bool) override { return value(); }
    bool number_integer(number_integer_t) override { return value(); }
    bool number_unsigned(number_unsigned_t) override { return value(); }
    bool number_float(number_float_t, const string_t&) override { return value(); }
    bool string(string_t&) override { return value(); }
    bool binary(binary_t&) override { return value(); }
    bool start_object(std::size_t) override { return open(false); }
    bool key(string_t& k) override {
        frames_.back().key = k;
        return true;
    }
    bool end_object() override { return close(); }
    bool start_array(std::size_t) override { return open(true); }
    bool end_array() override { return close(); }
    bool parse_error(std::size_t, const std::string& last_token, const nlohmann::detail::exception&) override {
        for (const Frame& f : frames_) pointer = f.array ? child(pointer, f.index) : child(pointer, f.key);
        token = last_token;
        return false;
    }

private:
    struct Frame {
        bool array = false;
        std::size_t index = 0;
        std::string key;
    };
    bool value() {
        if (!frames_.empty() && frames_.back().array) ++frames_.back().index;
        return true;
    }
    bool open(bool array) {
        frames_.push_back({array, 0, {}});
        return true;
    }
    bool close() {
        frames_.pop_back();
        return value();
    }
    std::vector<Frame> frames_;
};

}  // namespace

json parse_text(std::string_view text, const std::string& where) {
    try {
        return json::parse(text.begin(), text.end());
    } catch (const json::parse_error& e) {
        throw Error(where + "JSON syntax error at byte " + std::to_string(e.byte) + ": " +
                    std::string(e.what()).substr(std::string(e.what()).find(':') + 2));
    } catch (const json::out_of_range& e) {
        // A number past the range of a double: found again, with its place, by a second parse.
        PointerTracker tracker;
        json::sax_parse(text.begin(), text.end(), &tracker);
        if (!tracker.token.empty())
            throw Error(where + (tracker.pointer.empty() ? "/" : tracker.pointer) + ": number out of range (got " + tracker.token + ")");
        throw Error(where + "invalid JSON: " + e.what());
    } catch (const json::exception& e) {
        throw Error(where + "invalid JSON: " + e.what());
    }
}


}  // namespace grape::scene_io
