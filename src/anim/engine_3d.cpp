// 3-D animations: validation, the frame table built once, and the update (position, offsets along
// the frame, the orientation member). Timing, events, timelines and targets are the engine's own:
// a 3-D record is a custom record whose Extra holds a Track3.
#include "engine_3d.hpp"
#include "engine_impl.hpp"

#include <grape/error.hpp>

#include "path3/node3.hpp"

#include <cmath>
#include <string>

namespace grape::detail {

namespace {

const char* axis3_name(Axis3 a) noexcept {
    switch (a) {
        case Axis3::pos_x: return "pos_x";
        case Axis3::neg_x: return "neg_x";
        case Axis3::pos_y: return "pos_y";
        case Axis3::neg_y: return "neg_y";
        case Axis3::pos_z: return "pos_z";
        case Axis3::neg_z: return "neg_z";
    }
    return "an unknown axis";
}

bool axis3_valid(Axis3 a) noexcept { return static_cast<unsigned>(a) <= static_cast<unsigned>(Axis3::neg_z); }

// The signed pick of model axis e among f (→ tangent, 1), u (→ normal, 2), s = f × u (→ binormal, 3).
std::int8_t pick3_of(Vec3 e, Vec3 f, Vec3 u, Vec3 s) noexcept {
    if (const double c = dot(e, f); c != 0.0) return static_cast<std::int8_t>(c > 0.0 ? 1 : -1);
    if (const double c = dot(e, u); c != 0.0) return static_cast<std::int8_t>(c > 0.0 ? 2 : -2);
    return static_cast<std::int8_t>(dot(e, s) > 0.0 ? 3 : -3);
}

Vec3 picked3(std::int8_t pick, Vec3 t, Vec3 n, Vec3 b) noexcept {
    const int k = pick < 0 ? -pick : pick;
    const Vec3 v = k == 1 ? t : k == 2 ? n : b;
    return pick < 0 ? -v : v;
}

void validate_motion3(const std::string& w, const AnimationDef& def, const Motion3Def& m, const Layout3& layout,
                      bool bound) {
    for (const auto& [name, u] : {std::pair{"range_start", def.range_start}, std::pair{"range_end", def.range_end}})
        if (!(u >= 0.0 && u <= 1.0)) throw Error(w + ": " + name + " must be in [0, 1] (got " + number_text(u) + ")");
    if (def.heading) throw Error(w + ": heading is for 2-D animations; turn a 3-D target with motion.align");
    if (def.offset != 0.0)
        throw Error(w + ": offset is for 2-D animations; use motion.normal_offset and motion.binormal_offset (got " +
                    number_text(def.offset) + ")");
    if (static_cast<unsigned>(m.align) > static_cast<unsigned>(Align3::world))
        throw Error(w + ": align must be none, frame or world (got " + std::to_string(static_cast<unsigned>(m.align)) + ")");
    if (!axis3_valid(m.forward)) throw Error(w + ": forward is not an axis (got " + std::to_string(static_cast<unsigned>(m.forward)) + ")");
    if (!axis3_valid(m.up)) throw Error(w + ": up is not an axis (got " + std::to_string(static_cast<unsigned>(m.up)) + ")");
    if (dot(axis_vector(m.forward), axis_vector(m.up)) != 0.0)
        throw Error(w + ": forward and up must be perpendicular axes (got " + axis3_name(m.forward) + " and " +
                    axis3_name(m.up) + ")");
    if (!is_finite(m.world_up) || length(m.world_up) == 0.0 || !std::isfinite(length(m.world_up)))
        throw Error(w + ": world_up must be finite and not zero (got (" + number_text(m.world_up.x) + ", " +
                    number_text(m.world_up.y) + ", " + number_text(m.world_up.z) + "))");
    if (!std::isfinite(m.normal_offset))
        throw Error(w + ": normal_offset must be finite (got " + number_text(m.normal_offset) + ")");
    if (!std::isfinite(m.binormal_offset))
        throw Error(w + ": binormal_offset must be finite (got " + number_text(m.binormal_offset) + ")");
    if (bound && m.align != Align3::none && layout.member == Orient3Member::none)
        throw Error(w + ": align needs an `orientation` member in the target (a grape::Frame3, grape::Basis or grape::Quat)");
}

}  // namespace

Animation EngineImpl::create_3d(void* object, const Layout3& layout, std::unique_ptr<TargetRef> ref,
                                const Path3& path, double duration, const Speed* speed, const AnimationDef& def,
                                const Motion3Def& m) {
    const std::string w = "create_3d_animation";
    if (!object) throw Error(w + ": the target is null");
    validate_motion3(w, def, m, layout, true);
    auto track = std::make_shared<Track3>();
    track->path = path;
    if (speed) {
        const double v = speed->units_per_second;
        if (!(std::isfinite(v) && v > 0.0)) throw Error(w + ": speed must be positive and finite (got " + number_text(v) + ")");
        const double length = path.length();
        if (!(length > 0.0)) throw Error(w + ": speed needs a path of positive length (got length " + number_text(length) + ")");
        duration = length / v;
        if (!(std::isfinite(duration) && duration > 0.0))
            throw Error(w + ": length / speed must be positive and finite (length " + number_text(length) + ", speed " +
                        number_text(v) + ")");
        track->path = path.reparametrized();  // unchanged (no work) if it already is
    }
    validate(w, duration, def);
    const bool offsets = m.normal_offset != 0.0 || m.binormal_offset != 0.0;
    if (m.align == Align3::frame || offsets) {
        if (m.shared_frames) {
            if (&Path3Access::node(m.shared_frames->path()) != &Path3Access::node(track->path))
                throw Error(w + ": shared_frames must frame the path played" +
                            std::string(speed ? " (in speed mode: path.reparametrized())" : ""));
            track->frames = m.shared_frames;
        } else {
            try {
                track->frames = std::make_shared<const Frames3>(track->path, m.frames);
            } catch (const Error& e) {
                throw Error(w + ": frames: " + e.what());
            }
        }
    }
    track->layout = layout;
    track->align = m.align;
    track->face_travel = m.face_travel;
    track->world_up = normalized(m.world_up);
    track->normal_offset = m.normal_offset;
    track->binormal_offset = m.binormal_offset;
    const Vec3 f = axis_vector(m.forward), u = axis_vector(m.up), s = cross(f, u);
    track->pick = {pick3_of({1, 0, 0}, f, u, s), pick3_of({0, 1, 0}, f, u, s), pick3_of({0, 0, 1}, f, u, s)};

    Hot h = custom_hot(object, duration, def);
    Extra extra;
    extra.p3 = std::move(track);
    extra.ref = std::move(ref);
    extra.overwrite = def.overwrite;
    extra.range_start = def.range_start;
    extra.range_end = def.range_end;
    if (def.repeat_delay > 0.0 && def.repeat != 0) {
        extra.repeat_gap = def.repeat_delay / duration;
        h.flags |= flag_listens;
    }
    {  // readable while waiting: where the first play starts
        Track3& t = *extra.p3;
        const double at = along_range(extra, def.reversed ? 1.0 : 0.0);
        t.position = t.path.point(at);
        if (t.frames && offsets) {
            const Frame3 fr = t.frames->frame(at);
            t.position = t.position + fr.normal * t.normal_offset + fr.binormal * t.binormal_offset;
        }
    }
    h.path = acquire_path(Path());  // shared placeholder: the 3-D path is in the Track3
    const std::uint16_t curve = acquire_curve_for(h.path, def.curve);
    const Animation a = add(h, curve, duration, def, std::move(extra));
    if (find(a.slot_, a.generation_)) remember_scale(a.slot_, def.time_scale);  // unless a handler killed it
    return a;
}

void EngineImpl::write_3d(const Hot& h, Extra& e, double u) const noexcept {
    Track3& t = *e.p3;
    const double at = along_range(e, u);
    Vec3 p = t.path.point(at);
    Frame3 fr{};
    if (t.frames) {
        fr = t.frames->frame(at);
        if (t.normal_offset != 0.0 || t.binormal_offset != 0.0)
            p = p + fr.normal * t.normal_offset + fr.binormal * t.binormal_offset;
    }
    t.position = p;
    char* base = h.target;
    if (!base) return;
    const Layout3& l = t.layout;
    if (l.is_float) {
        *reinterpret_cast<float*>(base + l.x) = static_cast<float>(p.x);
        *reinterpret_cast<float*>(base + l.y) = static_cast<float>(p.y);
        *reinterpret_cast<float*>(base + l.z) = static_cast<float>(p.z);
    } else {
        *reinterpret_cast<double*>(base + l.x) = p.x;
        *reinterpret_cast<double*>(base + l.y) = p.y;
        *reinterpret_cast<double*>(base + l.z) = p.z;
    }
    if (t.align == Align3::none || l.member == Orient3Member::none) return;
    Vec3 tangent, normal, binormal;
    if (t.align == Align3::frame) {
        tangent = fr.tangent;
        normal = fr.normal;
        binormal = fr.binormal;
    } else {
        const Vec3 up = t.world_up;
        const Vec3 d = t.path.tangent(at);
        const Vec3 level = d - up * dot(d, up);
        // |level| = sin of the angle between tangent and up: below 1e-9 rad it has no direction.
        tangent = length(level) > 1e-9 ? normalized(level) : any_perpendicular(up);
        normal = up;
        binormal = cross(tangent, up);
    }
    const bool backward = ((h.flags & flag_backward) != 0) != (e.range_end < e.range_start);
    if (t.face_travel && backward) {  // a half turn about the normal
        tangent = -tangent;
        binormal = -binormal;
    }
    char* o = base + l.orientation;
    switch (l.member) {
        case Orient3Member::frame:
            *reinterpret_cast<Frame3*>(o) = Frame3{p, tangent, normal, binormal};
            break;
        case Orient3Member::basis:
            *reinterpret_cast<Basis*>(o) = Basis{picked3(t.pick[0], tangent, normal, binormal),
                                                  picked3(t.pick[1], tangent, normal, binormal),
                                                  picked3(t.pick[2], tangent, normal, binormal)};
            break;
        case Orient3Member::quat:
            // the basis is orthonormal within a few ulp by construction (a frame, or ±level and up)
            *reinterpret_cast<Quat*>(o) = from_basis_unchecked(picked3(t.pick[0], tangent, normal, binormal),
                                                               picked3(t.pick[1], tangent, normal, binormal),
                                                               picked3(t.pick[2], tangent, normal, binormal));
            break;
        default: break;
    }
}

Vec3 EngineImpl::value3_of(std::uint32_t dense) const noexcept {
    const Extra* e = (hot_[dense].flags & flag_custom) ? extra(cold_[dense].slot) : nullptr;
    return e && e->p3 ? e->p3->position : Vec3{};
}

}  // namespace grape::detail

namespace grape {

Animation Engine::create_bound_3d(void* object, const detail::Layout3& layout, std::unique_ptr<detail::TargetRef> ref,
                                  const Path3& path, double duration, const Speed* speed, const AnimationDef& def,
                                  const Motion3Def& motion) {
    return impl_->create_3d(object, layout, std::move(ref), path, duration, speed, def, motion);
}

Vec3 Animation::value3() const noexcept {
    const auto r = record();
    return r ? r.impl->value3_of(r.dense) : Vec3{};
}

}  // namespace grape
