// What a 3-D record keeps beside its Extra: the path played, the frame table, where it writes,
// and how the model's axes take the frame's.
#pragma once

#include <grape/anim.hpp>

#include <array>
#include <cstdint>
#include <memory>

namespace grape::detail {

struct Track3 {
    Path3 path;                             // played (reparametrized in speed mode)
    std::shared_ptr<const Frames3> frames;  // null unless aligned to the frame or offset along it
    Layout3 layout;                         // byte offsets from the target (h.target: the object)
    Align3 align = Align3::none;
    bool face_travel = true;
    Vec3 world_up{0.0, 0.0, 1.0};           // unit
    double normal_offset = 0.0;
    double binormal_offset = 0.0;
    // Model axis i (x, y, z) takes ±(tangent, normal, binormal)[|pick[i]| − 1]: a signed pick,
    // so that a Basis is the frame's vectors themselves, bit for bit.
    std::array<std::int8_t, 3> pick{};
    Vec3 position{};                        // the position last evaluated (Animation::value3)
};

}  // namespace grape::detail
