// Beads on grape::Path values (kept apart from bead.cpp so that programs using only user
// curves do not need the path module's code).
#include <grape/dynamics.hpp>

namespace grape {

namespace {
// ü = (x′·F/m − (x′·x″)u̇²)/|x′|² divides by the speed: a path of length 0 (SVG data that
// draws nothing) has none anywhere.
void require_length(const Path& path) {
    if (!(path.length() > 0.0))
        throw Error("Bead: the path has length 0 (it stands at one point), so there is nothing to slide along");
}

ParametricFunction curve_of(const Path& path) {
    return [path](double u) { return ParametricSample{path.point(u), path.d1(u), path.d2(u)}; };
}
}  // namespace

Bead::Bead(const Path& path, const BeadDef& def) {
    require_length(path);
    std::vector<Part> parts;
    if (const auto complex = path_cast<ComplexSpec>(path)) {
        // One part per top-level part of a complex path, so joins keep the speed along it.
        for (std::size_t i = 0; i < complex->parts.size(); ++i) {
            const double u0 = complex->cues[i];
            const double u1 = i + 1 < complex->parts.size() ? complex->cues[i + 1] : 1.0;
            if (u1 > u0) parts.push_back({curve_of(complex->parts[i]), u0, u1});  // empty spans are skipped, as the path does
        }
        if (parts.empty()) throw Error("Bead: path has no part with a non-empty span");
    } else {
        parts.push_back({curve_of(path), 0.0, 1.0});
    }
    init_parts(std::move(parts), def);
}

Bead::Bead(const ComplexPath& path, const BeadDef& def) : Bead(static_cast<const Path&>(path), def) {}

}  // namespace grape
