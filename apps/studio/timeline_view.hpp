// The Paths tab's timeline view: a scene's top-level timelines as rows of bars on one axis of
// scene time (every play drawn, backward plays mirrored), labels as ticks, and a playhead
// the mouse drags to seek the scene time.
#pragma once

#include <grape/scene.hpp>

#include <imgui.h>

#include <string>
#include <vector>

namespace grape::studio {

class TimelineView {
public:
    /// Shows the timelines of `scene` (checked: it was loaded); none leaves the view empty.
    void set_scene(const Scene& scene);
    /// No timelines: the view takes no room.
    bool empty() const noexcept { return rows_.empty(); }
    /// Pixels of height the view needs.
    float height() const noexcept;
    /// Draws into [min, max]; a left drag there moves the playhead and sets `time` (scene
    /// seconds, within the axis). Returns true while the playhead is held.
    bool draw(ImDrawList* dl, ImVec2 min, ImVec2 max, double& time);
    /// Seconds of scene time the axis spans.
    double span() const noexcept { return span_; }
    /// Screen x of the axis' start and end, from the last draw (for scripted checks).
    float axis_start() const noexcept { return axis_x0_; }
    float axis_end() const noexcept { return axis_x1_; }

private:
    struct Bar {
        double from = 0.0, to = 0.0;  // scene seconds
        ImU32 color = 0;
        std::string text;             // a nested timeline's name
        bool tick = false;            // a label
    };
    struct Row {
        std::string name;
        std::vector<Bar> bars;
    };
    std::vector<Row> rows_;
    double span_ = 1.0;
    bool dragging_ = false;
    float axis_x0_ = 0.0f, axis_x1_ = 0.0f;
};

}  // namespace grape::studio
