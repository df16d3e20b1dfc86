// SVG path data → absolute segments (svg_parser.hpp): the grammar (SVG 1.1 §8.3.9 / SVG 2
// §9.3.9), its scanner and the command state. The arc conversion (F.6.5, F.6.6) is in
// svg_arc.cpp; the segments become a ComplexPath in svg_path.cpp.
#include "svg_parser.hpp"

#include "path_node.hpp"

#include <grape/error.hpp>
#include <grape/path.hpp>

#include "math/number_text.hpp"

#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <system_error>

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
        const auto [end, ec] = parse_double(digits_only.data(), digits_only.data() + digits_only.size(), value);
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

    // The pair after the separator that follows the previous one.
    Vec2 next_pair(bool relative) {
        scan_.skip_comma_wsp();
        return pair(relative);
    }

    Vec2 absolute(Vec2 p, bool relative) const {
        const Vec2 q = relative ? current_ + p : p;
        if (!is_finite(q)) fail_range("a coordinate is too large", group_at_);
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
            const Vec2 c2 = next_pair(relative);
            cubic(c1, c2, next_pair(relative));
            return;
        }
        case 'S': {
            // The first control point mirrors the previous cubic's second one about the
            // current point; without a previous C or S it is the current point itself.
            const Vec2 c1 = previous_ == Previous::cubic ? 2.0 * current_ - control_ : current_;
            if (!is_finite(c1)) fail_range("a reflected control point is too large", group_at_);
            const Vec2 c2 = pair(relative);
            cubic(c1, c2, next_pair(relative));
            return;
        }
        case 'Q': {
            const Vec2 c = pair(relative);
            quadratic(c, next_pair(relative));
            return;
        }
        case 'T': {
            const Vec2 c = previous_ == Previous::quadratic ? 2.0 * current_ - control_ : current_;
            if (!is_finite(c)) fail_range("a reflected control point is too large", group_at_);
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

SvgCommands parse_svg_segments(std::string_view data) {
    Scanner scan(data);
    return Builder(scan).run();
}

}  // namespace grape::detail
