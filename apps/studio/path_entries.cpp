// The Paths tab's entries: movable points through the path's public description.
#include "path_entries.hpp"

#include <catalogue.hpp>

#include <algorithm>
#include <span>
#include <variant>

namespace grape::studio {

namespace {

// The spec whose points a drag edits: a reparametrized path's source (the same shape).
PathSpec editable_spec(const Path& path) {
    PathSpec spec = describe(path);
    if (const auto* r = std::get_if<ReparametrizedSpec>(&spec)) return describe(r->source);
    return spec;
}

// The spec's movable points: a Bézier's control points or a spline's points (none for the
// other kinds).
std::span<Vec2> points_of(PathSpec& spec) {
    return std::visit([](auto& s) -> std::span<Vec2> {
        if constexpr (requires { s.control; }) return s.control;
        else if constexpr (requires { s.points; }) return s.points;
        else return {};
    }, spec);
}

}  // namespace

PathEntry entry_from_path(std::string name, const Path& path) {
    PathEntry e;
    e.name = std::move(name);
    e.path = path;
    PathSpec spec = editable_spec(path);
    const auto points = points_of(spec);
    e.controls.assign(points.begin(), points.end());
    e.bezier = kind_of(spec) == PathKind::quadratic_bezier || kind_of(spec) == PathKind::cubic_bezier;
    return e;
}

std::vector<PathEntry> path_catalogue() {
    std::vector<PathEntry> entries;
    for (const scenes::Entry* e : scenes::entries_of(scenes::Category::path)) entries.push_back(entry_from_path(e->name, e->path()));
    return entries;
}

Path rebuild(const PathEntry& e) {
    PathSpec spec = editable_spec(e.path);
    const auto points = points_of(spec);
    std::copy_n(e.controls.begin(), std::min(points.size(), e.controls.size()), points.begin());
    const Path path = from_spec(spec);
    return e.path.kind() == PathKind::reparametrized ? path.reparametrized() : path;
}

}  // namespace grape::studio
