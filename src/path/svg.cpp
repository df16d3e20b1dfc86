// SVG path data → ComplexPath. The grammar (SVG 1.1 §8.3.9 / SVG 2 §9.3.9) and the arc
// conversion of the SVG implementation notes (F.6.5, F.6.6) turn the text into absolute
// segments (svg_parser.hpp); each drawn segment then becomes one part (a line, a Bézier or an
// exact elliptical arc) of a ComplexPath with cues by length.
#include "svg_parser.hpp"

#include "path_node.hpp"

#include <grape/error.hpp>
#include <grape/path.hpp>

#include <charconv>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <optional>
#include <string>

namespace grape::detail {
namespace {

bool is_wsp(char c) noexcept { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f'; }
bool is_digit(char c) noexcept { return c >= '0' && c <= '9'; }

// What the scanner found where it wanted something else, for the error message.
std::string describe(std::string_view data, std::size_t at) {
    if (at >= data.size()) return "the end of the data";
    const auto c = static_cast<unsigned char>(data[at]);
    char buffer[32];
    if (c >= 0x21 && c < 0x7f) {
        std::snprintf(buffer, sizeof buffer, "'%c'", static_cast<char>(c));
    } else {
        std::snprintf(buffer, sizeof buffer, "byte 0x%02x", static_cast<unsigned>(c));
    }
    return buffer;
}

// The first error in the data: where, and the message. Caught by Builder::run, which keeps
// the commands read before it (SVG's error rule).
struct SyntaxError {
    std::size_t offset;
    std::string message;
};

[[noreturn]] void fail(std::string_view data, std::string_view expected, std::size_t at) {
    throw SyntaxError{at, "SVG path data: expected " + std::string(expected) + " at offset " + std::to_string(at) +
                              ", found " + describe(data, at)};
}

[[noreturn]] void fail_range(std::string_view what, std::size_t at) {
    throw SyntaxError{at, "SVG path data: " + std::string(what) + " at offset " + std::to_string(at) +
                              " (beyond the range of a double)"};
}

// The digits of a number that overflowed or underflowed: which way did it go? The decimal
// exponent of the leading significant digit, saturated so that it cannot overflow itself.
bool lexeme_is_tiny(std::string_view lexeme) noexcept {
    bool seen_point = false;
    bool found = false;
    std::size_t i = 0;
    long integer_digits = 0;
    long leading_fraction_zeros = 0;
    for (; i < lexeme.size(); ++i) {
        const char c = lexeme[i];
        if (c == '+' || c == '-') continue;
        if (c == '.') { seen_point = true; continue; }
        if (!is_digit(c)) break;
        if (!seen_point) {
            if (c != '0' || integer_digits > 0) ++integer_digits;
            if (c != '0') found = true;
        } else if (!found) {
            if (c == '0') ++leading_fraction_zeros; else found = true;
        }
        if (integer_digits > 100000) integer_digits = 100000;
        if (leading_fraction_zeros > 100000) leading_fraction_zeros = 100000;
    }
    if (!found) return true;  // all zeros: cannot overflow, treat as zero
    // Position of the first non-zero digit relative to the decimal point.
    const long magnitude = integer_digits > 0 ? integer_digits : -leading_fraction_zeros;
    long exponent = 0;
    if (i < lexeme.size() && (lexeme[i] == 'e' || lexeme[i] == 'E')) {
        ++i;
        bool negative = false;
        if (i < lexeme.size() && (lexeme[i] == '+' || lexeme[i] == '-')) negative = lexeme[i++] == '-';
        for (; i < lexeme.size() && is_digit(lexeme[i]); ++i) {
            exponent = exponent * 10 + (lexeme[i] - '0');
            if (exponent > 1000000) exponent = 1000000;
        }
        if (negative) exponent = -exponent;
    }
    return magnitude + exponent < 0;
}

// Reads the grammar's tokens from the data; every `expect_*` throws with the offset.
class Scanner {
public:
    explicit Scanner(std::string_view data) noexcept : data_(data) {}

    std::size_t offset() const noexcept { return at_; }
    bool at_end() const noexcept { return at_ >= data_.size(); }
    char peek() const noexcept { return at_end() ? '\0' : data_[at_]; }
    void advance() noexcept { ++at_; }
    std::string_view data() const noexcept { return data_; }

    void skip_wsp() noexcept {
        while (!at_end() && is_wsp(data_[at_])) ++at_;
    }

    /// comma-wsp? of the grammar: whitespace, at most one comma, whitespace. True if a comma was read.
    bool skip_comma_wsp() noexcept {
        skip_wsp();
        if (peek() != ',') return false;
        ++at_;
        skip_wsp();
        return true;
    }

    bool at_number() const noexcept {
        const char c = peek();
        return is_digit(c) || c == '.' || c == '+' || c == '-';
    }

    /// number: sign? (digits '.' digits? | '.' digits | digits) exponent?
    /// A second '.' ends the number, so ".5.5" is two numbers, as browsers read it.
    double expect_number() {
        const std::size_t start = at_;
        std::size_t i = at_;
        if (i < data_.size() && (data_[i] == '+' || data_[i] == '-')) ++i;
        std::size_t digits = 0;
        while (i < data_.size() && is_digit(data_[i])) { ++i; ++digits; }
        if (i < data_.size() && data_[i] == '.') {
            ++i;
            std::size_t fraction = 0;
            while (i < data_.size() && is_digit(data_[i])) { ++i; ++fraction; }
            digits += fraction;
        }
        if (digits == 0) fail(data_, "a number", start);
        if (i < data_.size() && (data_[i] == 'e' || data_[i] == 'E')) {
            ++i;
            if (i < data_.size() && (data_[i] == '+' || data_[i] == '-')) ++i;
            if (i >= data_.size() || !is_digit(data_[i])) fail(data_, "the digits of an exponent", i);
            while (i < data_.size() && is_digit(data_[i])) ++i;
        }
        at_ = i;
        std::string_view lexeme = data_.substr(start, i - start);
        const std::string_view digits_only = lexeme.front() == '+' ? lexeme.substr(1) : lexeme;
        double value = 0.0;
        const auto [end, ec] = std::from_chars(digits_only.data(), digits_only.data() + digits_only.size(), value);
        if (ec == std::errc::result_out_of_range) {
            // Underflow rounds to a signed zero, as a browser would; overflow is an error.
            if (!lexeme_is_tiny(lexeme)) fail_range("a number is too large", start);
            return lexeme.front() == '-' ? -0.0 : 0.0;
        }
        if (ec != std::errc() || end != digits_only.data() + digits_only.size() || !std::isfinite(value)) {
            fail(data_, "a number", start);  // not reachable for lexemes of the grammar
        }
        return value;
    }

    /// flag: '0' | '1', a single character (so "a1 1 0 00 1 1" reads the flags 0 and 0).
    bool expect_flag() {
        const char c = peek();
        if (c != '0' && c != '1') fail(data_, "an arc flag (0 or 1)", at_);
        ++at_;
        return c == '1';
    }

private:
    std::string_view data_;
    std::size_t at_ = 0;
};

// cos and sin of an angle in degrees, exact at multiples of 90° so that axis-aligned arcs
// (the usual case) carry no rounding from the rotation.
void cos_sin_degrees(double degrees, double& c, double& s) noexcept {
    if (degrees == 0.0) { c = 1.0; s = 0.0; return; }
    if (degrees == 90.0) { c = 0.0; s = 1.0; return; }
    if (degrees == 180.0) { c = -1.0; s = 0.0; return; }
    if (degrees == 270.0) { c = 0.0; s = -1.0; return; }
    const double radians = degrees * (pi / 180.0);
    c = std::cos(radians);
    s = std::sin(radians);
}

bool finite(Vec2 p) noexcept { return std::isfinite(p.x) && std::isfinite(p.y); }

// The command state of the grammar: current point, subpath start and the control point the
// S and T commands reflect.
class Builder {
public:
    explicit Builder(Scanner& scan) noexcept : scan_(scan) {}

    // Every argument group either completes (and appends its commands) or throws before
    // appending anything, so what is in segments_ when an error is caught is the valid prefix.
    SvgCommands run() {
        SvgCommands out;
        try {
            scan_.skip_wsp();
            // SVG 2: empty data is no error; it draws nothing.
            if (!scan_.at_end()) {
                const char first = scan_.peek();
                if (first != 'M' && first != 'm') fail(scan_.data(), "a moveto (M or m)", scan_.offset());
            }
            while (true) {
                scan_.skip_wsp();
                if (scan_.at_end()) break;
                const std::size_t command_at = scan_.offset();
                const char letter = scan_.peek();
                command(letter, command_at);
            }
        } catch (SyntaxError& e) {
            out.ok = false;
            out.error_offset = e.offset;
            out.error = std::move(e.message);
        }
        out.commands = std::move(segments_);
        return out;
    }

private:
    enum class Previous { other, cubic, quadratic };

    void command(char letter, std::size_t command_at) {
        const bool relative = letter >= 'a' && letter <= 'z';
        const char upper = relative ? static_cast<char>(letter - 'a' + 'A') : letter;
        switch (upper) {
        case 'M': case 'L': case 'H': case 'V': case 'C': case 'S': case 'Q': case 'T': case 'A': case 'Z':
            break;
        default:
            fail(scan_.data(), "a command letter (M, L, H, V, C, S, Q, T, A or Z)", command_at);
        }
        scan_.advance();
        if (upper == 'Z') {
            close(command_at);
            return;
        }
        scan_.skip_wsp();
        char current = upper;
        while (true) {
            group_at_ = scan_.offset();
            argument_group(current, relative);
            // After a moveto, further coordinate pairs are implicit linetos.
            if (current == 'M') current = 'L';
            const bool comma = scan_.skip_comma_wsp();
            if (scan_.at_number()) continue;
            if (comma) fail(scan_.data(), "a number", scan_.offset());
            break;
        }
    }

    Vec2 pair(bool relative) {
        const double x = scan_.expect_number();
        scan_.skip_comma_wsp();
        const double y = scan_.expect_number();
        return absolute({x, y}, relative);
    }

    Vec2 absolute(Vec2 p, bool relative) const {
        const Vec2 q = relative ? current_ + p : p;
        if (!finite(q)) fail_range("a coordinate is too large", group_at_);
        return q;
    }

    void argument_group(char command, bool relative) {
        switch (command) {
        case 'M': {
            const Vec2 p = pair(relative);
            current_ = start_ = p;
            ++subpath_;
            previous_ = Previous::other;
            SvgSegment s = segment(SvgSegment::Kind::move);
            s.p[0] = p;
            segments_.push_back(s);
            return;
        }
        case 'L': line(pair(relative)); break;
        case 'H': {
            const double x = scan_.expect_number();
            line(absolute({x, relative ? 0.0 : current_.y}, relative));
            break;
        }
        case 'V': {
            const double y = scan_.expect_number();
            line(absolute({relative ? 0.0 : current_.x, y}, relative));
            break;
        }
        case 'C': {
            const Vec2 c1 = pair(relative);
            scan_.skip_comma_wsp();
            const Vec2 c2 = pair(relative);
            scan_.skip_comma_wsp();
            const Vec2 end = pair(relative);
            cubic(c1, c2, end);
            return;
        }
        case 'S': {
            // The first control point mirrors the previous cubic's second one about the
            // current point; without a previous C or S it is the current point itself.
            const Vec2 c1 = previous_ == Previous::cubic ? 2.0 * current_ - control_ : current_;
            if (!finite(c1)) fail_range("a reflected control point is too large", group_at_);
            const Vec2 c2 = pair(relative);
            scan_.skip_comma_wsp();
            const Vec2 end = pair(relative);
            cubic(c1, c2, end);
            return;
        }
        case 'Q': {
            const Vec2 c = pair(relative);
            scan_.skip_comma_wsp();
            const Vec2 end = pair(relative);
            quadratic(c, end);
            return;
        }
        case 'T': {
            const Vec2 c = previous_ == Previous::quadratic ? 2.0 * current_ - control_ : current_;
            if (!finite(c)) fail_range("a reflected control point is too large", group_at_);
            quadratic(c, pair(relative));
            return;
        }
        case 'A': {
            const double rx = scan_.expect_number();
            scan_.skip_comma_wsp();
            const double ry = scan_.expect_number();
            scan_.skip_comma_wsp();
            const double rotation = scan_.expect_number();
            scan_.skip_comma_wsp();
            const bool large_arc = scan_.expect_flag();
            scan_.skip_comma_wsp();
            const bool sweep = scan_.expect_flag();
            scan_.skip_comma_wsp();
            arc(rx, ry, rotation, large_arc, sweep, pair(relative));
            break;
        }
        default: break;
        }
        previous_ = Previous::other;
    }

    SvgSegment segment(SvgSegment::Kind kind) const noexcept {
        SvgSegment s;
        s.kind = kind;
        s.subpath = subpath_;
        s.offset = group_at_;
        return s;
    }

    void line(Vec2 end, bool closing = false) {
        SvgSegment s = segment(SvgSegment::Kind::line);
        s.p[0] = current_;
        s.p[1] = end;
        s.zero_length = end == current_;
        s.closing = closing;
        // Z at the subpath's start adds no line of its own (the close draws the dot).
        if (!(closing && s.zero_length)) segments_.push_back(s);
        current_ = end;
    }

    void quadratic(Vec2 c, Vec2 end) {
        SvgSegment s = segment(SvgSegment::Kind::quadratic);
        s.p = {current_, c, end, Vec2{}};
        s.zero_length = c == current_ && end == current_;
        segments_.push_back(s);
        control_ = c;
        previous_ = Previous::quadratic;
        current_ = end;
    }

    void cubic(Vec2 c1, Vec2 c2, Vec2 end) {
        SvgSegment s = segment(SvgSegment::Kind::cubic);
        s.p = {current_, c1, c2, end};
        s.zero_length = c1 == current_ && c2 == current_ && end == current_;
        segments_.push_back(s);
        control_ = c2;
        previous_ = Previous::cubic;
        current_ = end;
    }

    void arc(double rx, double ry, double rotation, bool large_arc, bool sweep, Vec2 end) {
        // F.6.2: an arc whose endpoints coincide is omitted; a zero radius makes it a line.
        if (end == current_) return;
        SvgSegment s = segment(SvgSegment::Kind::arc);
        if (!svg_arc_to_center(current_, end, rx, ry, rotation, large_arc, sweep, s)) {
            line(end);
            return;
        }
        segments_.push_back(s);
        current_ = end;
    }

    void close(std::size_t command_at) {
        group_at_ = command_at;
        line(start_, true);  // the closing segment; the next command starts at the subpath's start
        SvgSegment s = segment(SvgSegment::Kind::close);
        s.p[0] = start_;
        segments_.push_back(s);
        previous_ = Previous::other;
    }

    Scanner& scan_;
    std::vector<SvgSegment> segments_;
    Vec2 current_{};
    Vec2 start_{};
    Vec2 control_{};
    Previous previous_ = Previous::other;
    int subpath_ = -1;
    std::size_t group_at_ = 0;
};

}  // namespace

bool svg_arc_to_center(Vec2 from, Vec2 to, double rx, double ry, double rotation_degrees, bool large_arc,
                       bool sweep, SvgSegment& out) noexcept {
    rx = std::abs(rx);
    ry = std::abs(ry);
    if (rx == 0.0 || ry == 0.0 || !std::isfinite(rotation_degrees)) return false;
    double degrees = std::fmod(rotation_degrees, 360.0);
    if (degrees < 0.0) degrees += 360.0;
    if (degrees >= 360.0) degrees = 0.0;  // fmod of a tiny negative angle rounds up to 360
    double c = 1.0;
    double s = 0.0;
    cos_sin_degrees(degrees, c, s);

    // Half the chord in the ellipse's own axes (F.6.5.1), halved before subtracting so that
    // endpoints near ±DBL_MAX do not overflow.
    const Vec2 half = from * 0.5 - to * 0.5;
    const double x1 = c * half.x + s * half.y;
    const double y1 = -s * half.x + c * half.y;
    const double h = std::hypot(x1, y1);
    if (!(h > 0.0) || !std::isfinite(h)) return false;
    // Everything below is written with the unit chord direction (xu, yu) and the axis ratio q,
    // so radii many orders of magnitude from the chord neither overflow nor underflow.
    const double xu = x1 / h;
    const double yu = y1 / h;
    const double q = rx / ry;
    if (!(q > 0.0) || !std::isfinite(q)) return false;  // an ellipse flatter than a double holds
    // n² is the SVG notes' Λ: above 1 the radii are too small to reach and are scaled up (F.6.6).
    // Divided directly, x1/rx is exact for the common just-reaching arc (a half circle drawn
    // from its diameter); h·hypot(xu/rx, yu/ry) rounds 1 to 1 − 2⁻⁵³ there, and the square
    // root below turns that into a center offset of 1.5e-8 radii. An overflow gives n = inf:
    // scaled up; an underflow gives n ≈ 0, where the offset is √(1 − n²) ≈ 1 anyway.
    const double n = std::hypot(x1 / rx, y1 / ry);
    // Radii that reach to within a few ulps (decimal data that only rounds to just-reaching:
    // icons draw circles as two half-arcs) reach exactly: the center is the chord's midpoint.
    constexpr double reach_tolerance = 8.0 * std::numeric_limits<double>::epsilon();
    const bool just_reaching = std::abs(1.0 - n * n) <= reach_tolerance;
    double cx = 0.0;
    double cy = 0.0;
    if (just_reaching) {
        // cx = cy = 0 and the radii as given.
    } else if (!(n < 1.0)) {
        rx = h * std::hypot(xu, yu * q);
        ry = h * std::hypot(xu / q, yu);
        if (!std::isfinite(rx) || !std::isfinite(ry)) return false;
    } else {
        // F.6.5.2 divided through by rx²·ry²: the center sits sqrt(1/Λ − 1) half-chords off.
        const double k = std::sqrt((1.0 - n) * (1.0 + n)) * (large_arc == sweep ? -1.0 : 1.0);
        cx = k * rx * (yu / std::hypot(xu / q, yu));
        cy = -k * ry * (xu / std::hypot(xu, yu * q));
    }
    // F.6.5.5–6: start angle and sweep, measured on the unit circle the ellipse maps to.
    const double theta1 = std::atan2((y1 - cy) / ry, (x1 - cx) / rx);
    const double theta2 = std::atan2((-y1 - cy) / ry, (-x1 - cx) / rx);
    double delta = theta2 - theta1;
    if (sweep && delta < 0.0) delta += 2.0 * pi;
    if (!sweep && delta > 0.0) delta -= 2.0 * pi;
    if (delta == 0.0) {
        // The chord vanished against the radii: the small arc is the chord itself, the large
        // one the whole ellipse.
        if (!large_arc) return false;
        delta = sweep ? 2.0 * pi : -2.0 * pi;
    }
    const Vec2 mid = from * 0.5 + to * 0.5;
    out.kind = SvgSegment::Kind::arc;
    out.p[0] = from;
    out.p[1] = to;
    out.center = Vec2{c * cx - s * cy, s * cx + c * cy} + mid;
    out.rx = rx;
    out.ry = ry;
    out.rotation = degrees * (pi / 180.0);
    out.start_angle = theta1;
    out.end_angle = theta1 + delta;
    return finite(out.center);
}

SvgCommands parse_svg_segments(std::string_view data) {
    Scanner scan(data);
    return Builder(scan).run();
}

}  // namespace grape::detail

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
