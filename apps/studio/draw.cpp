// The canvas: world ↔ screen mapping, handles and drawing helpers over ImGui's draw list.
#include "studio.hpp"

#include <algorithm>
#include <cmath>

namespace grape::studio {

ViewCanvas::ViewCanvas(ImDrawList* draw_list, ImVec2 screen_min, ImVec2 screen_max, Vec2 world_min, Vec2 world_max,
                       double margin_px)
    : draw_list_(draw_list), screen_min_(screen_min), screen_max_(screen_max) {
    const double w = std::max(1.0, double(screen_max.x - screen_min.x) - 2.0 * margin_px);
    const double h = std::max(1.0, double(screen_max.y - screen_min.y) - 2.0 * margin_px);
    const Vec2 size = world_max - world_min;
    scale_ = std::min(w / std::max(size.x, 1e-9), h / std::max(size.y, 1e-9));
    const Vec2 screen_center{0.5 * (screen_min.x + screen_max.x), 0.5 * (screen_min.y + screen_max.y)};
    offset_ = screen_center - 0.5 * (world_min + world_max) * scale_;
    // Hovered means over the canvas and not over a widget window on top of it.
    const ImVec2 m = ImGui::GetIO().MousePos;
    hovered_ = m.x >= screen_min.x && m.x < screen_max.x && m.y >= screen_min.y && m.y < screen_max.y &&
               ImGui::IsWindowHovered(ImGuiHoveredFlags_AllowWhenBlockedByActiveItem);
}

ImVec2 ViewCanvas::to_screen(Vec2 p) const noexcept {
    return {float(offset_.x + p.x * scale_), float(offset_.y + p.y * scale_)};
}

Vec2 ViewCanvas::to_world(ImVec2 p) const noexcept {
    return {(p.x - offset_.x) / scale_, (p.y - offset_.y) / scale_};
}

bool ViewCanvas::drag_handle(int id, Vec2& p, ImU32 color, double radius_px) {
    const ImGuiIO& io = ImGui::GetIO();
    const ImVec2 s = to_screen(p);
    const double dx = io.MousePos.x - s.x;
    const double dy = io.MousePos.y - s.y;
    const bool near = hovered_ && dx * dx + dy * dy <= (radius_px + 3.0) * (radius_px + 3.0);
    if (held_ < 0 && near && ImGui::IsMouseClicked(ImGuiMouseButton_Left)) held_ = id;
    bool changed = false;
    if (held_ == id) {
        if (!ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
            held_ = -1;
        } else {
            const Vec2 m = mouse();
            if (is_finite(m) && !(m == p)) {
                p = m;
                changed = true;
            }
        }
    }
    const float r = float(radius_px);
    const ImVec2 c = to_screen(p);
    draw_list_->AddCircleFilled(c, r, (near || held_ == id) ? color::marker : color);
    draw_list_->AddCircle(c, r, color::ink, 0, 1.0f);
    return changed;
}

int ViewCanvas::active_handle() noexcept { return held_; }
void ViewCanvas::release_handle() noexcept { held_ = -1; }

void ViewCanvas::polyline(const std::vector<Vec2>& points, ImU32 color, float width) const {
    if (points.size() < 2) return;
    std::vector<ImVec2> screen;
    screen.reserve(points.size());
    for (Vec2 p : points) screen.push_back(to_screen(p));
    draw_list_->AddPolyline(screen.data(), int(screen.size()), color, ImDrawFlags_None, width);
}

void ViewCanvas::line(Vec2 a, Vec2 b, ImU32 color, float width) const {
    draw_list_->AddLine(to_screen(a), to_screen(b), color, width);
}

void ViewCanvas::disc(Vec2 p, float radius_px, ImU32 color) const {
    draw_list_->AddCircleFilled(to_screen(p), radius_px, color);
}

void ViewCanvas::ring(Vec2 p, float radius_px, ImU32 color, float width) const {
    draw_list_->AddCircle(to_screen(p), radius_px, color, 0, width);
}

void ViewCanvas::text(Vec2 p, ImU32 color, std::string_view s) const {
    draw_list_->AddText(to_screen(p), color, s.data(), s.data() + s.size());
}

void ViewCanvas::grid(double step, ImU32 color) const {
    if (!(step > 0.0) || step * scale_ < 4.0) return;  // too dense to be useful
    const Vec2 lo = to_world(screen_min_);
    const Vec2 hi = to_world(screen_max_);
    for (double x = std::ceil(lo.x / step) * step; x <= hi.x; x += step) {
        const float sx = to_screen({x, 0.0}).x;
        draw_list_->AddLine({sx, screen_min_.y}, {sx, screen_max_.y}, color);
    }
    for (double y = std::ceil(lo.y / step) * step; y <= hi.y; y += step) {
        const float sy = to_screen({0.0, y}).y;
        draw_list_->AddLine({screen_min_.x, sy}, {screen_max_.x, sy}, color);
    }
}

}  // namespace grape::studio
