// The absolute segments of SVG path data → ComplexPath: each drawn segment becomes one part
// (a line, a Bézier or an exact elliptical arc) with cues by length; SVG's error rule for the
// prefix form.
#include "svg_parser.hpp"

#include "path_node.hpp"

#include <grape/error.hpp>
#include <grape/path.hpp>

#include <cmath>
#include <memory>
#include <string>

namespace grape {
namespace {

Path to_path(const detail::SvgSegment& s) {
    using Kind = detail::SvgSegment::Kind;
    switch (s.kind) {
    case Kind::line: return LinearPath(s.p[0], s.p[1]);
    case Kind::quadratic: return QuadraticBezierPath(s.p[0], s.p[1], s.p[2]);
    case Kind::cubic: return CubicBezierPath(s.p[0], s.p[1], s.p[2], s.p[3]);
    case Kind::move:
    case Kind::close: break;  // not drawn: callers skip them
    case Kind::arc:
        // A circular arc is a CirclePath (its rotation only shifts the angles); anything
        // else is the exact ellipse.
        if (s.rx == s.ry) {
            return CirclePath(s.center, s.rx, s.start_angle + s.rotation, s.end_angle + s.rotation);
        }
        return EllipticalArcPath(s.center, s.rx, s.ry, s.rotation, s.start_angle, s.end_angle);
    }
    return LinearPath(s.p[0], s.p[1]);
}

// A ComplexPath handle on an SvgNode.
class SvgComplexPath : public ComplexPath {
public:
    explicit SvgComplexPath(std::shared_ptr<const detail::PathNode> node) noexcept : ComplexPath(std::move(node)) {}
};

// The path of the commands. Strict: any error throws. Otherwise SVG's error rule: the path
// stops before the command holding the first error, which is reported.
SvgPathParse build(detail::SvgCommands parsed, bool strict) {
    std::optional<SvgPathError> error;
    if (!parsed.ok) {
        if (strict) throw Error(parsed.error);
        error = SvgPathError{parsed.error_offset, parsed.error};
    }
    std::vector<detail::SvgSegment>& commands = parsed.commands;
    std::vector<Path> drawn;
    drawn.reserve(commands.size());
    double total = 0.0;
    for (std::size_t i = 0; i < commands.size(); ++i) {
        const detail::SvgSegment& s = commands[i];
        if (!s.drawn() || s.zero_length) continue;
        std::string why;
        Path part;
        try {
            part = to_path(s);
        } catch (const Error& e) {
            // The parser's checks keep coordinates finite; a kind may still refuse extremes
            // (a length beyond a double). Say where in the data that segment came from.
            why = "SVG path data: the segment at offset " + std::to_string(s.offset) + " is not a valid path (" +
                  e.what() + ")";
        }
        // Cues are length ratios: an infinite length would make them NaN.
        if (why.empty() && !std::isfinite(total + part.length())) {
            why = "SVG path data: the path's length overflows a double (segment at offset " +
                  std::to_string(s.offset) + ")";
        }
        if (!why.empty()) {
            if (strict) throw Error(why);
            error = SvgPathError{s.offset, why};
            commands.resize(i);
            break;
        }
        total += part.length();
        drawn.push_back(std::move(part));
    }
    // A segment shorter than the rounding error of the whole length (2⁻⁵²·L) would get a cue
    // span no u can land in, and 1/span can overflow; leaving it out moves nothing by more
    // than that rounding error.
    std::vector<Path> parts;
    parts.reserve(drawn.size());
    for (Path& part : drawn) {
        if (part.length() > std::numeric_limits<double>::epsilon() * total) parts.push_back(std::move(part));
    }
    if (parts.empty()) {
        // Nothing of positive length (empty data, only movetos, zero-length segments, or
        // lengths that underflow): the path stands at its first point, the origin for none.
        Vec2 at{};
        for (const detail::SvgSegment& s : commands) {
            if (s.kind == detail::SvgSegment::Kind::move) {
                at = s.p[0];
                break;
            }
        }
        parts.push_back(LinearPath(at, at));
        total = 0.0;
    }
    // Cues by length, as ComplexPath::by_length sets them.
    std::vector<double> cues(parts.size());
    double s = 0.0;
    for (std::size_t i = 0; i < parts.size(); ++i) {
        cues[i] = total > 0.0 ? std::min(s / total, 1.0) : static_cast<double>(i) / static_cast<double>(parts.size());
        s += parts[i].length();
    }
    return SvgPathParse{
        SvgComplexPath(detail::make_node<detail::SvgNode>(std::move(parts), std::move(cues), std::move(commands))),
        std::move(error)};
}

}  // namespace

ComplexPath parse_svg_path(std::string_view data) { return build(detail::parse_svg_segments(data), true).path; }

SvgPathParse parse_svg_path_prefix(std::string_view data) { return build(detail::parse_svg_segments(data), false); }

}  // namespace grape
