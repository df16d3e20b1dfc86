#include "view_spec.hpp"

#include <grape/error.hpp>

#include "math/number_text.hpp"

#include <cmath>
#include <string>
#include <vector>

namespace grape::tool {

namespace {

[[noreturn]] void view_spec_error(std::string_view spec, const std::string& why) {
    throw Error("render: --view '" + std::string(spec) + "': " + why);
}

// The comma-separated numbers after the colon, each finite.
std::vector<double> view_spec_numbers(std::string_view spec, std::string_view list, const char* const* names,
                                      std::size_t most) {
    std::vector<double> out;
    for (std::size_t at = 0;;) {
        const std::size_t comma = list.find(',', at);
        const std::string_view item = list.substr(at, comma == std::string_view::npos ? std::string_view::npos : comma - at);
        if (out.size() == most) view_spec_error(spec, "takes at most " + std::to_string(most) + " numbers");
        double v = 0.0;
        if (!detail::parse_finite(item, v))
            view_spec_error(spec, std::string(names[out.size()]) + " must be a finite number (got '" + std::string(item) + "')");
        out.push_back(v);
        if (comma == std::string_view::npos) break;
        at = comma + 1;
    }
    return out;
}

}  // namespace

ViewSpec parse_view_spec(std::string_view spec) {
    const std::size_t colon = spec.find(':');
    const std::string_view kind = spec.substr(0, colon);
    ViewSpec v;
    if (kind == "oblique") {
        if (colon == std::string_view::npos) return v;
        static const char* const names[] = {"ANGLE_DEG", "RECEDE"};
        const auto n = view_spec_numbers(spec, spec.substr(colon + 1), names, 2);
        if (n.size() != 2) view_spec_error(spec, "expected oblique:ANGLE_DEG,RECEDE (two numbers)");
        v.angle = n[0];
        v.recede = n[1];
        if (!(v.recede > 0.0 && v.recede <= 1.0)) view_spec_error(spec, "RECEDE must lie in (0, 1] (got " + detail::number_text(v.recede) + ")");
        return v;
    }
    if (kind == "perspective") {
        v.perspective = true;
        if (colon == std::string_view::npos) return v;
        static const char* const names[] = {"AZIMUTH_DEG", "ELEVATION_DEG", "FOV_DEG"};
        const auto n = view_spec_numbers(spec, spec.substr(colon + 1), names, 3);
        if (n.size() < 2) view_spec_error(spec, "expected perspective:AZIMUTH_DEG,ELEVATION_DEG[,FOV_DEG] (two or three numbers)");
        v.azimuth = n[0];
        v.elevation = n[1];
        if (n.size() == 3) v.fov = n[2];
        // ±89°: nearer the poles the view runs along up and the picture's up side is undefined.
        if (!(std::fabs(v.elevation) <= 89.0))
            view_spec_error(spec, "ELEVATION_DEG must lie in [-89, 89] (got " + detail::number_text(v.elevation) + ")");
        // 120° at most: the camera then stands at 1/sin(60°) = 1.15 radii of the content's sphere.
        if (!(v.fov >= 5.0 && v.fov <= 120.0))
            view_spec_error(spec, "FOV_DEG must lie in [5, 120] (got " + detail::number_text(v.fov) + ")");
        return v;
    }
    view_spec_error(spec, "unknown view '" + std::string(kind) + "' (expected oblique, oblique:ANGLE_DEG,RECEDE, perspective or "
                    "perspective:AZIMUTH_DEG,ELEVATION_DEG[,FOV_DEG])");
}

}  // namespace grape::tool
