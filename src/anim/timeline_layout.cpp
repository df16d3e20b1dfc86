// Timeline positions: parsing GSAP's position syntax and resolving entries to start times.
#include <grape/error.hpp>
#include <grape/timeline_layout.hpp>

#include "math/number_text.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace grape {

namespace {

using Anchor = TimelinePosition::Anchor;

// A whole finite number (parse_finite's format: "1.5", "2", "1e-3", no sign in front).
bool read_number(std::string_view text, double& value) {
    if (text.empty() || text.front() == '+' || text.front() == '-') return false;
    return detail::parse_finite(text, value);
}

// "+0.5", "-0.2", "+=0.5", "-=0.2" → the signed offset.
bool read_offset(std::string_view text, double& offset) {
    if (text.size() < 2 || (text[0] != '+' && text[0] != '-')) return false;
    const double sign = text[0] == '-' ? -1.0 : 1.0;
    std::string_view rest = text.substr(1);
    if (!rest.empty() && rest[0] == '=') rest.remove_prefix(1);
    double magnitude = 0.0;
    if (!read_number(rest, magnitude)) return false;
    offset = sign * magnitude;
    return true;
}

[[noreturn]] void bad(std::string_view text, const std::string& why) {
    throw Error("timeline position '" + std::string(text) + "': " + why);
}

std::string seconds_text(double s) { return detail::general_text(s, 17); }

}  // namespace

TimelinePosition parse_timeline_position(std::string_view text) {
    TimelinePosition p;
    if (text.empty()) bad(text, "is empty");
    const char first = text.front();
    if (first == '>' || first == '<') {
        p.anchor = first == '>' ? Anchor::previous_end : Anchor::previous_start;
        if (text.size() > 1 && !read_offset(text.substr(1), p.offset))
            bad(text, std::string("expected '") + first + "' alone or followed by +N, -N, +=N or -=N");
        return p;
    }
    if (first == '+' || first == '-') {
        if (text.size() < 2 || text[1] != '=' || !read_offset(text, p.offset))
            bad(text, "a relative position is +=N or -=N with N a finite number");
        p.anchor = Anchor::end;
        return p;
    }
    if (std::isdigit(static_cast<unsigned char>(first)) || first == '.') {
        if (!read_number(text, p.offset)) bad(text, "is not a finite number of seconds");
        p.anchor = Anchor::start;
        return p;
    }
    if (first == '=') bad(text, "a label cannot start with '='");
    p.anchor = Anchor::label;
    // The label runs to the first sign that starts a valid offset.
    for (std::size_t k = 1; k < text.size(); ++k) {
        if ((text[k] == '+' || text[k] == '-') && read_offset(text.substr(k), p.offset)) {
            p.label = std::string(text.substr(0, k));
            return p;
        }
    }
    p.label = std::string(text);
    p.offset = 0.0;
    return p;
}

TimelinePosition timeline_position_at(double seconds) noexcept {
    TimelinePosition p;
    p.anchor = Anchor::start;
    p.offset = seconds;
    return p;
}

std::string to_string(const TimelinePosition& p) {
    const std::string magnitude = seconds_text(std::fabs(p.offset));
    const std::string signed_offset = p.offset == 0.0 ? "" : (p.offset < 0.0 ? "-=" : "+=") + magnitude;
    switch (p.anchor) {
        case Anchor::start: return seconds_text(p.offset);
        case Anchor::end: return p.offset < 0.0 ? "-=" + magnitude : "+=" + magnitude;
        case Anchor::previous_end: return ">" + signed_offset;
        case Anchor::previous_start: return "<" + signed_offset;
        case Anchor::label: return p.label + signed_offset;
    }
    return {};
}

TimelineLayout layout_timeline(std::span<const TimelineEntry> entries) {
    TimelineLayout out;
    out.start.reserve(entries.size());
    double end = 0.0;            // the latest end so far
    double previous_start = 0.0;  // of the previous child or gap
    double previous_end = 0.0;
    for (std::size_t i = 0; i < entries.size(); ++i) {
        const TimelineEntry& e = entries[i];
        const std::string where = "entries[" + std::to_string(i) + "]: ";
        const bool point = e.kind == TimelineEntry::Kind::label || e.kind == TimelineEntry::Kind::callback;
        const double duration = point ? 0.0 : e.duration;
        if (!(std::isfinite(duration) && duration >= 0.0))
            throw Error(where + "duration must be >= 0 and finite (got " + detail::number_text(e.duration) + ")");
        if (!std::isfinite(e.at.offset))
            throw Error(where + "position offset must be finite (got " + detail::number_text(e.at.offset) + ")");
        double start = 0.0;
        switch (e.at.anchor) {
            case Anchor::start: start = e.at.offset; break;
            case Anchor::end: start = end + e.at.offset; break;
            case Anchor::previous_end: start = previous_end + e.at.offset; break;
            case Anchor::previous_start: start = previous_start + e.at.offset; break;
            case Anchor::label: {
                const auto it = std::find_if(out.labels.begin(), out.labels.end(),
                                             [&](const auto& l) { return l.first == e.at.label; });
                if (it == out.labels.end())
                    throw Error(where + "unknown label '" + e.at.label + "' (labels must be defined before use)");
                start = it->second + e.at.offset;
                break;
            }
        }
        if (!(start >= 0.0))
            throw Error(where + "position '" + to_string(e.at) + "' gives a negative start (" +
                        detail::number_text(start) + " s)");
        if (!std::isfinite(start + duration))
            throw Error(where + "start + duration overflows (start " + detail::number_text(start) + ")");
        if (e.kind == TimelineEntry::Kind::label) {
            if (e.label.empty()) throw Error(where + "a label needs a name");
            const bool taken = std::any_of(out.labels.begin(), out.labels.end(),
                                           [&](const auto& l) { return l.first == e.label; });
            if (taken) throw Error(where + "duplicate label '" + e.label + "'");
            out.labels.emplace_back(e.label, start);
        }
        if (!point) {
            previous_start = start;
            previous_end = start + duration;
        }
        end = std::max(end, start + duration);
        out.start.push_back(start);
    }
    out.duration = end;
    return out;
}

double timeline_local_time(const AnimationDef& def, double duration, double t) noexcept {
    if (!(duration > 0.0)) return 0.0;
    const PlayState s = play_at(def, duration, t);
    const double phase = std::clamp(s.phase, 0.0, 1.0);
    return (s.backward ? 1.0 - phase : phase) * duration;
}

}  // namespace grape
