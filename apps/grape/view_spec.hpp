// `grape render --view SPEC`: how the scene's 3-D content is projected, read from the command
// line (oblique[:ANGLE_DEG,RECEDE] or perspective[:AZIMUTH_DEG,ELEVATION_DEG[,FOV_DEG]]).
#pragma once

#include <string_view>

namespace grape::tool {

/// A --view given on the command line, in degrees as written.
struct ViewSpec {
    bool perspective = false;
    double angle = 40.0;     // oblique: degrees above the horizontal the y axis recedes at
    double recede = 0.8;     // oblique: scale of the receding y axis, in (0, 1]
    double azimuth = -60.0;  // perspective: degrees about z from +x to the camera
    double elevation = 30.0; // perspective: degrees above the xy plane, in [−89, 89]
    double fov = 45.0;       // perspective: vertical field of view, degrees in [5, 120]
};

/// Reads SPEC without the locale; throws grape::Error "render: --view 'SPEC': WHY".
ViewSpec parse_view_spec(std::string_view spec);

}  // namespace grape::tool
