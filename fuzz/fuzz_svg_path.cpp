// libFuzzer target for grape::parse_svg_path: any byte string either parses into a path whose
// length and points are finite and whose derivatives are not NaN, or throws grape::Error with
// the parser's prefix.
// Anything else (a crash, a sanitizer report, another exception, a NaN) is a finding.
#include <grape/error.hpp>
#include <grape/path.hpp>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

namespace {

void require(bool condition) {
    if (!condition) std::abort();
}

bool is_nan(grape::Vec2 v) { return std::isnan(v.x) || std::isnan(v.y); }

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    // SVG's error rule never throws grape::Error; its path is a valid one (checked below
    // like the strict parse's), and its error names an offset inside the data.
    const grape::SvgPathParse prefix = grape::parse_svg_path_prefix(text);
    require(std::isfinite(prefix.path.length()) && prefix.path.length() >= 0.0);
    require(grape::is_finite(prefix.path.point(0.5)));
    if (prefix.error) require(prefix.error->offset <= size && prefix.error->message.starts_with("SVG path data: "));
    try {
        const grape::ComplexPath path = grape::parse_svg_path(text);
        require(!prefix.error);
        require(path.length() == prefix.path.length());
        const double length = path.length();
        // Data that draws nothing (empty, movetos only) is valid: length 0 at its point.
        require(std::isfinite(length) && length >= 0.0);
        const auto cues = path.cues();
        require(!cues.empty() && cues.front() == 0.0 && cues.size() == path.parts().size());
        for (std::size_t i = 1; i < cues.size(); ++i) require(cues[i - 1] <= cues[i] && cues[i] <= 1.0);
        // Points are finite. Derivatives are not NaN; they may overflow to ±inf when a part
        // spans a sliver of u next to one 1e200 times longer (the true value is that large).
        constexpr int samples = 16;
        for (int i = 0; i <= samples; ++i) {
            const double u = static_cast<double>(i) / samples;
            require(grape::is_finite(path.point(u)));
            require(!is_nan(path.d1(u)));
            require(!is_nan(path.d2(u)));
        }
    } catch (const grape::Error& e) {
        // Every rejection is the parser's own, with its prefix: a path constructor's error
        // escaping here means the parser let through something it should have caught.
        require(std::string_view(e.what()).starts_with("SVG path data: "));
    }
    return 0;
}
