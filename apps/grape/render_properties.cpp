// The property legend of `grape render`: one row per property, its value at the frame's time.
#include "render_properties.hpp"

#include <grape/scene_values.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <variant>

namespace grape::tool {

namespace {

// Rows beyond this are summarized: the legend must not cover the picture.
constexpr std::size_t max_rows = 12;

std::string number_text(double v) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.4g", v);
    return buffer;
}

}  // namespace

void draw_scene_properties(Canvas& canvas, const Scene& scene, const SceneTiming& timing, double t) {
    if (scene.properties.empty()) return;
    const SceneProperties values(scene, timing);
    const TextStyle style{.color = colors::black, .size = 10};
    const double right = canvas.width() - 10.0, width = 170.0, row = 14.0;
    const double left = std::max(10.0, right - width);
    const std::size_t shown = std::min(scene.properties.size(), max_rows);
    for (std::size_t k = 0; k < shown; ++k) {
        const SceneProperty& prop = scene.properties[k];
        const SceneValue v = values.value(k, t);
        const double y = 30.0 + row * static_cast<double>(k);
        std::string text = prop.name + " ";
        if (const Color* c = std::get_if<Color>(&v)) {
            const Color clamped{std::clamp(c->r, 0.0, 1.0), std::clamp(c->g, 0.0, 1.0), std::clamp(c->b, 0.0, 1.0),
                                std::clamp(c->a, 0.0, 1.0)};
            canvas.fill_rect({left, y - 9.0, 18.0, 11.0}, {.color = colors::black});
            canvas.fill_rect({left + 1.0, y - 8.0, 16.0, 9.0}, {.color = clamped});
            text += to_hex(*c);
        } else if (const Vec3* p3 = std::get_if<Vec3>(&v)) {
            text += '(';
            text += number_text(p3->x);
            text += ", ";
            text += number_text(p3->y);
            text += ", ";
            text += number_text(p3->z);
            text += ')';
        } else if (const Quat* q = std::get_if<Quat>(&v)) {
            text += "quat(";
            text += number_text(q->w);
            text += ", ";
            text += number_text(q->x);
            text += ", ";
            text += number_text(q->y);
            text += ", ";
            text += number_text(q->z);
            text += ')';
        } else if (const Vec2* p = std::get_if<Vec2>(&v)) {
            // Appended piece by piece: g++ 12 -O3 warns falsely (-Wrestrict) on "(" + string&&.
            text += '(';
            text += number_text(p->x);
            text += ", ";
            text += number_text(p->y);
            text += ')';
        } else {
            const double x = std::get<double>(v);
            if (prop.type == ScenePropertyType::angle) {
                const double radians = prop.degrees ? x * pi / 180.0 : x;
                const Vec2 center{left + 9.0, y - 3.5};
                canvas.stroke_line(center, center + Vec2{7.0 * std::cos(radians), 7.0 * std::sin(radians)},
                                   {.color = colors::black, .width = 1.5});
                text += number_text(x);
                text += prop.degrees ? "°" : " rad";
            } else {
                text += number_text(x);
            }
        }
        canvas.text({left + 24.0, y}, text, style);
    }
    if (scene.properties.size() > shown)
        canvas.text({left, 30.0 + row * static_cast<double>(shown)},
                    std::to_string(scene.properties.size() - shown) + " more properties", style);
}

}  // namespace grape::tool
