// Colours: the sRGB transfer curve, OKLab (Ottosson's published matrices), mixing with
// premultiplied alpha, CSS text both ways.
#include <grape/color.hpp>
#include <grape/error.hpp>

#include "math/number_text.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace grape {

double srgb_to_linear(double encoded) noexcept {
    const double c = std::abs(encoded);
    const double l = c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
    return std::copysign(l, encoded);
}

double linear_to_srgb(double linear) noexcept {
    const double l = std::abs(linear);
    const double c = l <= 0.0031308 ? 12.92 * l : 1.055 * std::pow(l, 1.0 / 2.4) - 0.055;
    return std::copysign(c, linear);
}

namespace {

using Mat3 = std::array<std::array<double, 3>, 3>;

// Ottosson's M1 (linear sRGB -> LMS) and M2 (cube-rooted LMS -> Lab), as published.
constexpr Mat3 m1{{{0.4122214708, 0.5363325363, 0.0514459929},
                   {0.2119034982, 0.6806995451, 0.1073969566},
                   {0.0883024619, 0.2817188376, 0.6299787005}}};
constexpr Mat3 m2{{{0.2104542553, 0.7936177850, -0.0040720468},
                   {1.9779984951, -2.4285922050, 0.4505937099},
                   {0.0259040371, 0.7827717662, -0.8086757660}}};

// The inverses in double precision (the published inverse matrices are accurate to float
// precision only, ~1e-7, which a round trip would show).
constexpr Mat3 inverse(const Mat3& m) {
    const double c00 = m[1][1] * m[2][2] - m[1][2] * m[2][1];
    const double c01 = m[1][2] * m[2][0] - m[1][0] * m[2][2];
    const double c02 = m[1][0] * m[2][1] - m[1][1] * m[2][0];
    const double det = m[0][0] * c00 + m[0][1] * c01 + m[0][2] * c02;
    return {{{c00 / det, (m[0][2] * m[2][1] - m[0][1] * m[2][2]) / det, (m[0][1] * m[1][2] - m[0][2] * m[1][1]) / det},
             {c01 / det, (m[0][0] * m[2][2] - m[0][2] * m[2][0]) / det, (m[0][2] * m[1][0] - m[0][0] * m[1][2]) / det},
             {c02 / det, (m[0][1] * m[2][0] - m[0][0] * m[2][1]) / det, (m[0][0] * m[1][1] - m[0][1] * m[1][0]) / det}}};
}
constexpr Mat3 m1_inverse = inverse(m1);
constexpr Mat3 m2_inverse = inverse(m2);

std::array<double, 3> times(const Mat3& m, double x, double y, double z) noexcept {
    return {m[0][0] * x + m[0][1] * y + m[0][2] * z, m[1][0] * x + m[1][1] * y + m[1][2] * z,
            m[2][0] * x + m[2][1] * y + m[2][2] * z};
}

Oklab linear_to_oklab(double r, double g, double b) noexcept {
    const auto lms = times(m1, r, g, b);
    const auto lab = times(m2, std::cbrt(lms[0]), std::cbrt(lms[1]), std::cbrt(lms[2]));
    return {lab[0], lab[1], lab[2]};
}

std::array<double, 3> oklab_to_linear(const Oklab& lab) noexcept {
    const auto root = times(m2_inverse, lab.L, lab.a, lab.b);
    return times(m1_inverse, root[0] * root[0] * root[0], root[1] * root[1] * root[1], root[2] * root[2] * root[2]);
}

}  // namespace

Oklab to_oklab(const Color& c) noexcept {
    return linear_to_oklab(srgb_to_linear(c.r), srgb_to_linear(c.g), srgb_to_linear(c.b));
}

Color from_oklab(const Oklab& lab, double alpha) noexcept {
    const auto rgb = oklab_to_linear(lab);
    return {linear_to_srgb(rgb[0]), linear_to_srgb(rgb[1]), linear_to_srgb(rgb[2]), alpha};
}

ColorMix::ColorMix(const Color& a, const Color& b, ColorSpace space) noexcept : a_(a), b_(b), space_(space) {
    if (space == ColorSpace::oklab) {
        const Oklab la = to_oklab(a), lb = to_oklab(b);
        pa_[0] = la.L, pa_[1] = la.a, pa_[2] = la.b;
        pb_[0] = lb.L, pb_[1] = lb.a, pb_[2] = lb.b;
    } else {
        pa_[0] = srgb_to_linear(a.r), pa_[1] = srgb_to_linear(a.g), pa_[2] = srgb_to_linear(a.b);
        pb_[0] = srgb_to_linear(b.r), pb_[1] = srgb_to_linear(b.g), pb_[2] = srgb_to_linear(b.b);
    }
}

Color ColorMix::operator()(double t) const noexcept {
    if (t == 0.0) return a_;
    if (t == 1.0) return b_;
    const double alpha = a_.a * (1.0 - t) + b_.a * t;
    // Premultiplied: each end's components weigh by its alpha. Where the mixed alpha is 0
    // there is no colour to recover; the components are then mixed without weights.
    const bool weigh = alpha > 0.0;
    const double wa = weigh ? a_.a * (1.0 - t) / alpha : 1.0 - t;
    const double wb = weigh ? b_.a * t / alpha : t;
    double m[3];
    for (int k = 0; k < 3; ++k) m[k] = pa_[k] * wa + pb_[k] * wb;
    if (space_ == ColorSpace::oklab) return from_oklab({m[0], m[1], m[2]}, alpha);
    return {linear_to_srgb(m[0]), linear_to_srgb(m[1]), linear_to_srgb(m[2]), alpha};
}

Color mix(const Color& a, const Color& b, double t, ColorSpace space) noexcept {
    if (t == 0.0) return a;
    if (t == 1.0) return b;
    return ColorMix(a, b, space)(t);
}

// --- CSS text ----------------------------------------------------------------------------------

namespace {

[[noreturn]] void bad_color(std::string_view text, const std::string& why) {
    throw Error("parse_color: \"" + std::string(text) + "\": " + why);
}

int hex_digit(char c) noexcept {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

Color parse_hex(std::string_view text, std::string_view digits) {
    const std::size_t n = digits.size();
    if (n != 3 && n != 4 && n != 6 && n != 8)
        bad_color(text, "a hex colour has 3, 4, 6 or 8 digits (got " + std::to_string(n) + ")");
    std::array<double, 4> v{0, 0, 0, 1};
    const std::size_t per = n <= 4 ? 1 : 2;
    for (std::size_t k = 0; k < n / per; ++k) {
        int value = 0;
        for (std::size_t j = 0; j < per; ++j) {
            const int d = hex_digit(digits[k * per + j]);
            if (d < 0) {
                std::string why(1, '\'');  // appended, not operator+: g++ 12 -O3 warns falsely there
                why += digits[k * per + j];
                why += "' is not a hex digit";
                bad_color(text, why);
            }
            value = value * 16 + d;
        }
        if (per == 1) value *= 17;  // #f00 is #ff0000
        v[k] = value / 255.0;
    }
    return {v[0], v[1], v[2], v[3]};
}

std::string_view trim(std::string_view s) noexcept {
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
    return s;
}

// One number with an optional %: channels are 0–255 or 0–100 %; alpha 0–1 or 0–100 %.
double parse_component(std::string_view text, std::string_view item, bool is_alpha, int index) {
    item = trim(item);
    const bool percent = !item.empty() && item.back() == '%';
    if (percent) item.remove_suffix(1);
    double value = 0.0;
    const std::string what = is_alpha ? "alpha" : "component " + std::to_string(index + 1);
    if (!detail::parse_finite(item, value))
        bad_color(text, what + " is not a number (\"" + std::string(item) + "\")");
    if (percent) value /= 100.0;
    else if (!is_alpha) value /= 255.0;
    return std::clamp(value, 0.0, 1.0);
}

Color parse_function(std::string_view text, std::string_view body) {
    // Either "r, g, b[, a]" or "r g b[ / a]".
    std::vector<std::string_view> items;
    std::string_view alpha;
    bool has_alpha = false;
    if (body.find(',') != std::string_view::npos) {
        std::size_t start = 0;
        for (std::size_t k = 0; k <= body.size(); ++k) {
            if (k == body.size() || body[k] == ',') {
                items.push_back(body.substr(start, k - start));
                start = k + 1;
            }
        }
        if (items.size() == 4) {
            alpha = items.back();
            has_alpha = true;
            items.pop_back();
        }
    } else {
        std::string_view rest = body;
        if (const std::size_t slash = body.find('/'); slash != std::string_view::npos) {
            alpha = body.substr(slash + 1);
            has_alpha = true;
            rest = body.substr(0, slash);
        }
        std::size_t k = 0;
        while (k < rest.size()) {
            while (k < rest.size() && std::isspace(static_cast<unsigned char>(rest[k]))) ++k;
            const std::size_t start = k;
            while (k < rest.size() && !std::isspace(static_cast<unsigned char>(rest[k]))) ++k;
            if (k > start) items.push_back(rest.substr(start, k - start));
        }
    }
    if (items.size() != 3)
        bad_color(text, "rgb() takes 3 components and an optional alpha (got " + std::to_string(items.size()) +
                      (has_alpha ? " and an alpha)" : ")"));
    Color c;
    c.r = parse_component(text, items[0], false, 0);
    c.g = parse_component(text, items[1], false, 1);
    c.b = parse_component(text, items[2], false, 2);
    if (has_alpha) c.a = parse_component(text, alpha, true, 3);
    return c;
}

}  // namespace

Color parse_color(std::string_view text) {
    const std::string_view s = trim(text);
    if (s.empty()) bad_color(text, "empty colour");
    if (s.front() == '#') return parse_hex(text, s.substr(1));
    std::string lower(s);
    for (char& ch : lower) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
    for (std::string_view name : {std::string_view("rgba("), std::string_view("rgb(")}) {
        if (lower.starts_with(name)) {
            if (s.back() != ')') bad_color(text, "missing ')'");
            return parse_function(text, s.substr(name.size(), s.size() - name.size() - 1));
        }
    }
    bad_color(text, "expected #rgb, #rgba, #rrggbb, #rrggbbaa, rgb(...) or rgba(...)");
}

namespace {
int byte_of(double v) noexcept { return static_cast<int>(std::lround(std::clamp(v, 0.0, 1.0) * 255.0)); }
}  // namespace

std::string to_hex(const Color& c) {
    char buffer[12];
    const int alpha = byte_of(c.a);
    if (alpha == 255) std::snprintf(buffer, sizeof buffer, "#%02x%02x%02x", byte_of(c.r), byte_of(c.g), byte_of(c.b));
    else std::snprintf(buffer, sizeof buffer, "#%02x%02x%02x%02x", byte_of(c.r), byte_of(c.g), byte_of(c.b), alpha);
    return buffer;
}

std::string to_css(const Color& c) {
    char buffer[64];
    const double alpha = std::clamp(c.a, 0.0, 1.0);
    if (alpha >= 1.0) {
        std::snprintf(buffer, sizeof buffer, "rgb(%d, %d, %d)", byte_of(c.r), byte_of(c.g), byte_of(c.b));
        return buffer;
    }
    std::snprintf(buffer, sizeof buffer, "rgba(%d, %d, %d, ", byte_of(c.r), byte_of(c.g), byte_of(c.b));
    std::string out = buffer + detail::fixed_text(alpha, 3) + ")";  // "0.500)" reads as "0.5)"
    const std::size_t close = out.size() - 1;
    std::size_t last = close;
    while (out[last - 1] == '0') --last;
    if (out[last - 1] == '.') --last;
    out.erase(last, close - last);
    return out;
}

}  // namespace grape
