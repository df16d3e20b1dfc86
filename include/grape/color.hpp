// grape — colours: RGBA as CSS and images give them (sRGB-encoded), read from and written to
// CSS text, interpolated in linear light or in OKLab, never in the encoded values (whose
// midpoints come out too dark: #ff0000 to #00ff00 passes #808000 there, #bcbc00 in linear
// light).
//
//   grape::Color red = grape::parse_color("#ff0000");
//   engine.animate(sprite, &Sprite::tint, grape::to(grape::parse_color("rgb(0 128 255)")), 1.0);
//   engine.animate(sprite, &Sprite::tint, grape::to(blue), 1.0, {}, grape::ColorLerp{grape::ColorSpace::oklab});
#pragma once

#include <grape/export_anim.hpp>
#include <grape/value.hpp>

#include <string>
#include <string_view>

namespace grape {

/// \addtogroup value
/// @{

/// An RGBA colour: r, g, b sRGB-encoded (the numbers of CSS, image files and most engines'
/// tints), each 1 at full intensity; a is coverage (0 transparent, 1 opaque). Interpolation
/// and extrapolation may leave [0, 1]; to_hex and to_css clamp.
struct Color {
    double r = 0.0;  ///< red, sRGB-encoded
    double g = 0.0;  ///< green, sRGB-encoded
    double b = 0.0;  ///< blue, sRGB-encoded
    double a = 1.0;  ///< alpha: 0 transparent, 1 opaque
    friend constexpr bool operator==(const Color&, const Color&) noexcept = default;  ///< all four components equal (exact)
};

/// Where colours are mixed.
enum class ColorSpace {
    linear_srgb,  ///< linear light (the sRGB primaries without the transfer curve): physical mixing
    oklab,        ///< Björn Ottosson's OKLab: even perceived steps, hue kept
};

/// The sRGB transfer curve (IEC 61966-2-1) from encoded to linear light; odd (negative values
/// mirror), so extrapolated colours stay defined.
GRAPE_ANIM_API double srgb_to_linear(double encoded) noexcept;
/// Its inverse: linear light to the encoded value.
GRAPE_ANIM_API double linear_to_srgb(double linear) noexcept;

/// A colour in OKLab: L lightness (0 black, 1 white), a green–red, b blue–yellow.
struct Oklab {
    double L = 0.0;  ///< lightness: 0 black, 1 white
    double a = 0.0;  ///< green (negative) to red (positive)
    double b = 0.0;  ///< blue (negative) to yellow (positive)
};
/// The colour's r, g, b in OKLab (alpha dropped).
GRAPE_ANIM_API Oklab to_oklab(const Color& c) noexcept;
/// The sRGB-encoded colour of an OKLab value, with alpha `alpha` (out of gamut: components
/// outside [0, 1]).
GRAPE_ANIM_API Color from_oklab(const Oklab& lab, double alpha = 1.0) noexcept;

/// Two colours converted once into `space`, mixed at any t: ColorMix(a, b, space)(t) is
/// mix(a, b, t, space), bit for bit.
class GRAPE_ANIM_API ColorMix {
public:
    ColorMix() noexcept = default;
    ColorMix(const Color& a, const Color& b, ColorSpace space) noexcept;  ///< converts `a` and `b` into `space` once
    Color operator()(double t) const noexcept;  ///< mix(a, b, t, space)

private:
    Color a_, b_;
    double pa_[3] = {}, pb_[3] = {};  // the ends' components in the space
    ColorSpace space_ = ColorSpace::linear_srgb;
};

/// (1 − t)·a + t·b mixed in `space` with premultiplied alpha, as CSS Color 4 interpolates (a
/// transparent end lends no colour); exactly a at t = 0 and b at t = 1.
GRAPE_ANIM_API Color mix(const Color& a, const Color& b, double t,
                         ColorSpace space = ColorSpace::linear_srgb) noexcept;
/// The interpolation typed animations use for colours (found by argument-dependent lookup):
/// linear light.
inline Color lerp(const Color& a, const Color& b, double t) noexcept { return mix(a, b, t); }

/// An interpolator for Engine::animate that mixes in a chosen space.
struct ColorLerp {
    ColorSpace space = ColorSpace::oklab;  ///< where to mix (OKLab by default)
    Color operator()(const Color& a, const Color& b, double t) const noexcept { return mix(a, b, t, space); }  ///< mix(a, b, t, space)
    ColorMix prepare(const Color& a, const Color& b) const noexcept { return ColorMix(a, b, space); }  ///< the ends converted once, for animations
};

/// Colours animate in linear light, their ends converted once.
template <>
struct Interpolate<Color> {
    static Color lerp(const Color& a, const Color& b, double t) noexcept { return mix(a, b, t); }  ///< mix(a, b, t) in linear light
    /// The ends converted to linear light once.
    static ColorMix prepare(const Color& a, const Color& b) noexcept {
        return ColorMix(a, b, ColorSpace::linear_srgb);
    }
};

/// A colour from CSS text: `#rgb`, `#rgba`, `#rrggbb`, `#rrggbbaa` (hex digits of either case)
/// and `rgb()` / `rgba()` with three numbers 0–255 or percentages and an optional alpha
/// (0–1 or a percentage), separated by commas or by spaces with `/` before the alpha:
/// "rgb(255, 0, 0)", "rgba(0,0,255,0.5)", "rgb(0 128 255 / 50%)". Values beyond the ranges
/// clamp, as CSS clamps them. Throws grape::Error naming the text and the reason otherwise.
GRAPE_ANIM_API Color parse_color(std::string_view text);
/// `#rrggbb`, or `#rrggbbaa` when alpha is below 1 (components clamped to [0, 1], rounded
/// to the nearest of 256 steps); parse_color reads it back to within half a step.
GRAPE_ANIM_API std::string to_hex(const Color& c);
/// `rgb(r, g, b)` with integers 0–255, or `rgba(r, g, b, a)` when alpha is below 1, a with
/// up to three decimals.
GRAPE_ANIM_API std::string to_css(const Color& c);

/// @}

}  // namespace grape
