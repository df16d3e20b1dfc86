// Animated SVG (SMIL): written as text, since cairo's SVG surface only makes still pictures.
#include <grape/render.hpp>

#include "math/number_text.hpp"

#include <algorithm>
#include <cmath>
#include <locale>
#include <sstream>

namespace grape {

namespace {

std::string number(double v) { return detail::fixed_text(std::isfinite(v) ? v : 0.0, 2); }

std::string rgb(Color c) {
    const auto channel = [](double v) { return static_cast<int>(std::lround(std::clamp(std::isfinite(v) ? v : 0.0, 0.0, 1.0) * 255.0)); };
    return "rgb(" + std::to_string(channel(c.r)) + "," + std::to_string(channel(c.g)) + "," + std::to_string(channel(c.b)) + ")";
}

std::string escape(std::string_view s) {
    std::string out;
    for (char c : s) {
        switch (c) {
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '&': out += "&amp;"; break;
            case '"': out += "&quot;"; break;
            default: out += c;
        }
    }
    return out;
}

}  // namespace

std::string animated_svg(double width, double height, const Affine& transform, std::span<const Path> paths,
                         std::span<const Color> path_colors, std::span<const SvgMover> movers, double seconds,
                         std::string_view title) {
    std::ostringstream svg;
    svg.imbue(std::locale::classic());  // numbers come as text; nothing the stream formats may group digits
    svg << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
        << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << number(width) << "\" height=\"" << number(height)
        << "\" viewBox=\"0 0 " << number(width) << ' ' << number(height) << "\">\n";
    if (!title.empty()) svg << "<title>" << escape(title) << "</title>\n";
    svg << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
    const double stretch = transform.max_stretch();
    const double tolerance = stretch > 0.0 && std::isfinite(stretch) ? 0.25 / stretch : 0.25;
    for (std::size_t i = 0; i < paths.size(); ++i) {
        const Color c = path_colors.empty() ? colors::black : path_colors[i % path_colors.size()];
        svg << "<path fill=\"none\" stroke-width=\"1.5\" stroke=\"" << rgb(c) << "\" d=\"";
        const auto points = paths[i].flatten(tolerance);
        for (std::size_t k = 0; k < points.size(); ++k) {
            const Vec2 p = transform.apply(points[k]);
            svg << (k == 0 ? "M" : " L") << number(p.x) << ' ' << number(p.y);
        }
        svg << "\"/>\n";
    }
    const std::string dur = detail::general_text(std::isfinite(seconds) && seconds > 0.0 ? seconds : 1.0, 6) + "s";
    for (const SvgMover& m : movers) {
        if (m.positions.empty()) continue;
        std::string xs, ys;
        for (std::size_t k = 0; k < m.positions.size(); ++k) {
            const Vec2 p = transform.apply(m.positions[k]);
            if (k > 0) {
                xs += ';';
                ys += ';';
            }
            xs += number(p.x);
            ys += number(p.y);
        }
        const Vec2 first = transform.apply(m.positions.front());
        svg << "<circle r=\"" << number(m.radius) << "\" stroke=\"black\" fill=\"" << rgb(m.color) << "\" cx=\""
            << number(first.x) << "\" cy=\"" << number(first.y) << "\">";
        if (!m.label.empty()) svg << "<title>" << escape(m.label) << "</title>";
        // Discrete steps: frame k shows exactly positions[k], as the PNG frames would.
        svg << "<animate attributeName=\"cx\" dur=\"" << dur << "\" repeatCount=\"indefinite\" calcMode=\"discrete\" values=\""
            << xs << "\"/>";
        svg << "<animate attributeName=\"cy\" dur=\"" << dur << "\" repeatCount=\"indefinite\" calcMode=\"discrete\" values=\""
            << ys << "\"/>";
        svg << "</circle>\n";
    }
    svg << "</svg>\n";
    return svg.str();
}

}  // namespace grape
