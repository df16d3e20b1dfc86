#include "timeline_view.hpp"

#include "studio.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <tuple>
#include <utility>

namespace grape::studio {

namespace {

// The bars of one row are bounded: a timeline repeating many times shows its first plays.
constexpr int max_plays = 64;
// A scene playing forever shows this many first plays of its longest timeline.
constexpr double forever_plays = 3.0;
constexpr float row_height = 18.0f;
constexpr float name_width = 80.0f;

const ImU32 bar_colors[] = {IM_COL32(200, 60, 70, 200), IM_COL32(40, 150, 80, 200), IM_COL32(120, 60, 170, 200),
                             IM_COL32(230, 130, 20, 200), IM_COL32(30, 140, 150, 200), IM_COL32(150, 100, 50, 200)};

}  // namespace

void TimelineView::set_scene(const Scene& scene) {
    rows_.clear();
    dragging_ = false;
    span_ = 0.0;
    if (scene.timelines.empty()) return;
    const SceneTiming timing(scene);
    // The axis: until every top-level timeline has ended, or a few plays of the forever ones.
    for (std::size_t k = 0; k < scene.timelines.size(); ++k) {
        const SceneTimelineLayout& layout = timing.layout(k);
        if (layout.parent >= 0) continue;
        const SceneTimeline& tl = scene.timelines[k];
        const double play = (tl.delay + forever_plays * (layout.duration + tl.repeat_delay)) / tl.time_scale;
        span_ = std::max(span_, std::isfinite(layout.end_time) ? layout.end_time : play);
    }
    if (!(span_ > 0.0)) span_ = 1.0;
    for (std::size_t k = 0; k < scene.timelines.size(); ++k) {
        const SceneTimelineLayout& layout = timing.layout(k);
        if (layout.parent >= 0) continue;
        const SceneTimeline& tl = scene.timelines[k];
        Row row{.name = tl.name, .bars = {}};
        const int plays = tl.repeat < 0 ? max_plays : std::min(tl.repeat + 1, max_plays);
        for (int p = 0; p < plays; ++p) {
            const double begin = (tl.delay + p * (layout.duration + tl.repeat_delay)) / tl.time_scale;
            if (begin > span_) break;
            const bool backward = tl.yoyo && p % 2 == 1;
            for (std::size_t c = 0; c < tl.children.size(); ++c) {
                const SceneTimelineChild& child = tl.children[c];
                if (child.kind == SceneTimelineChildKind::gap) continue;
                double a = layout.start[c], b = layout.start[c] + layout.length[c];
                if (backward) std::tie(a, b) = std::pair{layout.duration - b, layout.duration - a};
                Bar bar{.from = begin + a / tl.time_scale, .to = begin + b / tl.time_scale, .color = 0, .text = {}, .tick = false};
                switch (child.kind) {
                    case SceneTimelineChildKind::animation:
                        bar.color = bar_colors[static_cast<std::size_t>(layout.index[c]) % std::size(bar_colors)];
                        break;
                    case SceneTimelineChildKind::timeline:
                        bar.color = IM_COL32(130, 130, 140, 160);
                        bar.text = child.name;
                        break;
                    case SceneTimelineChildKind::label:
                        bar.color = color::ink;
                        bar.tick = true;
                        break;
                    case SceneTimelineChildKind::gap: break;
                    case SceneTimelineChildKind::animation3:  // a 3-D animation
                        bar.color = IM_COL32(80, 115, 180, 160);
                        bar.text = child.name;
                        break;
                    case SceneTimelineChildKind::tween:  // a property's tween
                        bar.color = IM_COL32(215, 150, 50, 160);
                        bar.text = child.name;
                        break;
                }
                row.bars.push_back(std::move(bar));
            }
        }
        rows_.push_back(std::move(row));
    }
}

float TimelineView::height() const noexcept { return rows_.empty() ? 0.0f : 22.0f + row_height * float(rows_.size()); }

bool TimelineView::draw(ImDrawList* dl, ImVec2 min, ImVec2 max, double& time) {
    if (rows_.empty()) return false;
    dl->AddRectFilled(min, max, IM_COL32(255, 255, 255, 235));
    dl->AddLine({min.x, min.y}, {max.x, min.y}, color::grid);
    axis_x0_ = min.x + name_width;
    axis_x1_ = std::max(axis_x0_ + 1.0f, max.x - 12.0f);
    const auto x_of = [&](double t) { return float(axis_x0_ + (axis_x1_ - axis_x0_) * std::clamp(t / span_, 0.0, 1.0)); };
    for (std::size_t r = 0; r < rows_.size(); ++r) {
        const float y = min.y + 6.0f + row_height * float(r);
        dl->AddText({min.x + 6.0f, y}, color::ink, rows_[r].name.c_str());
        dl->AddLine({axis_x0_, y + 8.0f}, {axis_x1_, y + 8.0f}, color::grid);
        for (const Bar& b : rows_[r].bars) {
            const float a = x_of(b.from), e = x_of(b.to);
            if (b.tick) {
                dl->AddLine({a, y}, {a, y + 16.0f}, b.color, 1.5f);
                continue;
            }
            dl->AddRectFilled({a, y + 2.0f}, {std::max(e, a + 1.0f), y + 14.0f}, b.color, 2.0f);
            if (!b.text.empty() && e - a > 30.0f) dl->AddText({a + 3.0f, y}, color::ink, b.text.c_str());
        }
    }
    char ends[64];
    std::snprintf(ends, sizeof ends, "%.2f s", span_);
    const float bottom = max.y - 14.0f;
    dl->AddText({axis_x0_, bottom}, color::faint, "0");
    dl->AddText({axis_x1_ - ImGui::CalcTextSize(ends).x, bottom}, color::faint, ends);

    // The playhead: a left press anywhere over the axis grabs it (unless a handle has the mouse).
    const ImVec2 m = ImGui::GetIO().MousePos;
    const bool over = m.x >= min.x && m.x < max.x && m.y >= min.y && m.y < max.y &&
                      ImGui::IsWindowHovered(ImGuiHoveredFlags_AllowWhenBlockedByActiveItem);
    if (!dragging_ && over && ViewCanvas::active_handle() < 0 && ImGui::IsMouseClicked(ImGuiMouseButton_Left)) dragging_ = true;
    if (dragging_ && !ImGui::IsMouseDown(ImGuiMouseButton_Left)) dragging_ = false;
    if (dragging_) time = span_ * std::clamp(double(m.x - axis_x0_) / double(axis_x1_ - axis_x0_), 0.0, 1.0);
    const float head = x_of(time);
    dl->AddLine({head, min.y + 2.0f}, {head, max.y - 16.0f}, color::marker, 2.0f);
    dl->AddTriangleFilled({head - 6.0f, min.y + 1.0f}, {head + 6.0f, min.y + 1.0f}, {head, min.y + 9.0f}, color::marker);
    char now[64];
    std::snprintf(now, sizeof now, "t = %.2f s", time);
    dl->AddText({std::min(head + 6.0f, axis_x1_ - 60.0f), bottom}, color::marker, now);
    return dragging_;
}

}  // namespace grape::studio
