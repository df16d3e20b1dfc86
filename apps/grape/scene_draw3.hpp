// The 3-D part of a `grape render` picture: the scene's 3-D paths projected by a View3 as
// polylines with small frames at even arc-length steps, and each 3-D animation's follower at
// the scene time as a dot with its frame's axes. Built once per render, drawn every frame.
#pragma once

#include <grape/render.hpp>
#include <grape/scene.hpp>
#include <grape/view3.hpp>

#include "view_spec.hpp"

#include <cstddef>
#include <string>
#include <vector>

namespace grape::tool {

/// True when the scene has 3-D paths or 3-D animations.
bool has_3d_content(const Scene& scene);

/// The colour of 3-D animation i's follower (the palette from its fifth colour on).
Color follower_colour(std::size_t i);

/// The scene's 3-D content seen through one view, fitted to a width × height picture.
class Scene3Picture {
public:
    /// Builds the view and the fit (no flattening yet). The 3-D box is the content's bounds
    /// grown by the follower axes' length on every side; a perspective orbit looks at its centre
    /// from fov/2 off the box's bounding sphere, so nothing drawn lies behind the camera.
    Scene3Picture(const Scene& scene, const ViewSpec& spec, double width, double height);

    /// An upper bound on the picture length (output units) of every 3-D path drawn, and the
    /// longest one's share and name: checked against the budget before flatten().
    double drawn_length_bound(double& longest, std::string& longest_name) const;
    /// Flattens the paths to a quarter of an output unit on the picture, builds the frames.
    void prepare();

    /// Draws the paths, their frames and every follower at scene time t.
    void draw(Canvas& canvas, const SceneTiming& timing, double t) const;

    /// Where a world point lands on the picture (output units).
    Vec2 to_picture(Vec3 p) const noexcept { return fit_.apply(view_.project(p).point); }
    /// Every path's picture polyline (after prepare), and each follower's position at t.
    const std::vector<std::vector<Vec2>>& polylines() const noexcept { return lines_; }
    Vec2 follower(const SceneTiming& timing, std::size_t i, double t) const noexcept;

private:
    struct Drawn3 {
        Path3 path;
        std::string name;
    };
    const Scene& scene_;
    View3 view_;
    Affine fit_;
    double stretch_ = 1.0;      // output units per world unit at most, anywhere in the box
    double path_axis_ = 0.0;    // world length of a path frame's axes
    double follower_axis_ = 0.0;  // world length of a follower's axes
    std::vector<Drawn3> paths_;
    std::vector<std::vector<Vec2>> lines_;
    std::vector<std::vector<Frame3>> frames_;  // per path, at even arc-length steps
    std::vector<SceneMotion3> motions_;
};

}  // namespace grape::tool
