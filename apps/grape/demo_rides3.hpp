// The demo's rides in 3-D (demo_rides3.cpp): a closed coaster track with a loop, banked
// automatically for its speed, and a camera on a rail with its frames and its own view.
#pragma once

#include <grape/render.hpp>

#include <string>

namespace grape::tool {

/// The coaster's ribbon rolled by bank_track, in perspective; figures: speed, max bank and where.
Canvas coaster_picture(std::string& figures);

/// The camera rail seen from outside with the camera's frames at several times, and the
/// picture the camera itself sees at one of them; figures: the rail's length and the times.
Canvas camera_rail_picture(std::string& figures);

}  // namespace grape::tool
