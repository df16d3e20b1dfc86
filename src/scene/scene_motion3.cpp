// 3-D animations of a scene evaluated: the path played, the frame table and the roll built
// once, then the position and orientation at any progress as the engine's 3-D record writes
// them (src/anim/engine_3d.cpp), with the roll on top of the frame.
#include <grape/scene_animation3.hpp>

#include <grape/error.hpp>

#include <cmath>
#include <string>
#include <vector>

namespace grape {

namespace {

// The signed pick of model axis e among f (→ tangent, 1), u (→ normal, 2), s = f × u (→ binormal, 3):
// the engine's rule, so that the orientation is the engine's bit for bit.
std::int8_t motion3_pick(Vec3 e, Vec3 f, Vec3 u, Vec3 s) noexcept {
    if (const double c = dot(e, f); c != 0.0) return static_cast<std::int8_t>(c > 0.0 ? 1 : -1);
    if (const double c = dot(e, u); c != 0.0) return static_cast<std::int8_t>(c > 0.0 ? 2 : -2);
    return static_cast<std::int8_t>(dot(e, s) > 0.0 ? 3 : -3);
}

Vec3 motion3_picked(std::int8_t pick, Vec3 t, Vec3 n, Vec3 b) noexcept {
    const int k = pick < 0 ? -pick : pick;
    const Vec3 v = k == 1 ? t : k == 2 ? n : b;
    return pick < 0 ? -v : v;
}

FrameMode frame_mode_of(SceneFrameMode m) noexcept {
    switch (m) {
        case SceneFrameMode::rmf: return FrameMode::rotation_minimizing;
        case SceneFrameMode::frenet: return FrameMode::frenet;
        case SceneFrameMode::up: return FrameMode::reference_up;
    }
    return FrameMode::rotation_minimizing;
}

}  // namespace

double SceneAnimation3::seconds() const noexcept { return speed > 0.0 ? path.length() / speed : duration; }

AnimationDef SceneAnimation3::def() const noexcept {
    AnimationDef d{.curve = curve, .delay = delay, .repeat = repeat, .reversed = reversed, .yoyo = yoyo};
    d.repeat_delay = repeat_delay;
    d.range_start = range_start;
    d.range_end = range_end;
    return d;
}

Motion3Def SceneAnimation3::motion() const noexcept {
    Motion3Def m;
    m.align = align;
    m.frames = FramesDef{.mode = frame_mode_of(frame), .up = up, .cone = cone};
    m.world_up = up;
    m.forward = forward;
    m.up = model_up;
    m.face_travel = face_travel;
    m.normal_offset = normal_offset;
    m.binormal_offset = binormal_offset;
    return m;
}

double SceneAnimation3::end_time() const noexcept {
    const double d = seconds();
    return d > 0.0 ? grape::end_time(def(), d) : 0.0;
}

SceneMotion3::SceneMotion3(const SceneAnimation3& a) {
    path_ = a.path;
    if (a.speed > 0.0) {
        if (!std::isfinite(a.speed)) throw Error("speed: must be finite (got " + detail::number_text(a.speed) + ")");
        if (!(a.path.length() > 0.0)) throw Error("speed: needs a path of positive length (got length " +
                                                  detail::number_text(a.path.length()) + ")");
        path_ = a.path.reparametrized();
    }
    range_start_ = a.range_start;
    range_end_ = a.range_end;
    align_ = a.align;
    face_travel_ = a.face_travel;
    if (!is_finite(a.up) || !(length(a.up) > 0.0) || !std::isfinite(length(a.up)))
        throw Error("frame: up: must be finite and not zero");
    world_up_ = normalized(a.up);
    normal_offset_ = a.normal_offset;
    binormal_offset_ = a.binormal_offset;
    const Vec3 f = axis_vector(a.forward), u = axis_vector(a.model_up), s = cross(f, u);
    if (dot(f, u) != 0.0) throw Error("axes: forward and up must be perpendicular axes");
    pick_ = {motion3_pick({1, 0, 0}, f, u, s), motion3_pick({0, 1, 0}, f, u, s), motion3_pick({0, 0, 1}, f, u, s)};
    const bool rolled = !a.roll.empty() || a.banked;
    if (rolled && a.align != Align3::frame)
        throw Error(std::string(a.banked ? "bank" : "roll") + ": rolls the frame the target is turned by: it needs \"align\": \"frame\"");
    if (a.banked && a.frame != SceneFrameMode::up)
        throw Error("bank: banking tilts an upright frame: it needs \"frame\": {\"mode\": \"up\"}");
    if (a.keyed()) {
        if (a.align != Align3::none) throw Error("orientation: keys give the orientation themselves: they need \"align\": \"keys\"");
        if (rolled) throw Error(std::string(a.banked ? "bank" : "roll") + ": rolls a frame, and orientation keys replace it");
        std::vector<double> at;
        std::vector<Quat> q;
        at.reserve(a.orientation.size());
        q.reserve(a.orientation.size());
        for (const SceneOrientationKey& k : a.orientation) {
            at.push_back(k.s);
            q.push_back(k.q);
        }
        try {
            keys_ = std::make_shared<const QuatSpline>(std::move(at), std::move(q));
        } catch (const Error& e) {
            throw Error(std::string("orientation: ") + e.what());
        }
    }
    if (!(a.align == Align3::frame || a.normal_offset != 0.0 || a.binormal_offset != 0.0 || rolled)) return;
    try {
        frames_ = std::make_shared<const Frames3>(path_, a.motion().frames);
    } catch (const Error& e) {
        throw Error(std::string("frame: ") + e.what());
    }
    if (!rolled) return;
    RollTrack track;
    if (a.banked) {
        const BankDef bank{.speed = a.bank.speed, .gravity = a.bank.gravity, .max_angle = a.bank.max_angle, .up = a.up,
                           .smoothing = a.bank.smoothing, .samples = a.bank.samples};
        try {
            track = bank_track(path_, bank);
        } catch (const Error& e) {
            throw Error(std::string("bank: ") + e.what());
        }
    } else {
        try {
            track = RollTrack(a.roll);
        } catch (const Error& e) {
            throw Error(std::string("roll: ") + e.what());
        }
    }
    rolled_ = std::make_shared<const RolledFrames3>(*frames_, std::move(track));
}

Frame3 SceneMotion3::frame_at(double p) const noexcept {
    const double at = u_at(p);
    if (rolled_) return rolled_->frame(at);
    if (frames_) return frames_->frame(at);
    Frame3 f{};
    f.point = path_.point(at);
    return f;
}

Vec3 SceneMotion3::position_at(double p) const noexcept {
    const double at = u_at(p);
    Vec3 point = path_.point(at);
    if (frames_ && (normal_offset_ != 0.0 || binormal_offset_ != 0.0)) {
        const Frame3 fr = rolled_ ? rolled_->frame(at) : frames_->frame(at);
        point = point + fr.normal * normal_offset_ + fr.binormal * binormal_offset_;
    }
    return point;
}

Quat SceneMotion3::orientation_at(double p, bool backward) const noexcept {
    const double at = u_at(p);
    // The path played has the length of the path written (reparametrizing keeps it).
    if (keys_) return keys_->orientation(path_.length_at(at));
    if (align_ == Align3::none) return Quat{};
    Vec3 tangent, normal, binormal;
    if (align_ == Align3::frame) {
        const Frame3 fr = rolled_ ? rolled_->frame(at) : frames_->frame(at);
        tangent = fr.tangent;
        normal = fr.normal;
        binormal = fr.binormal;
    } else {
        const Vec3 d = path_.tangent(at);
        const Vec3 level = d - world_up_ * dot(d, world_up_);
        // |level| = sin of the angle between tangent and up: below 1e-9 rad it has no direction
        // (the engine's threshold).
        tangent = length(level) > 1e-9 ? normalized(level) : any_perpendicular(world_up_);
        normal = world_up_;
        binormal = cross(tangent, world_up_);
    }
    if (face_travel_ && (backward != (range_end_ < range_start_))) {  // a half turn about the normal
        tangent = -tangent;
        binormal = -binormal;
    }
    return from_basis_unchecked(motion3_picked(pick_[0], tangent, normal, binormal),
                                motion3_picked(pick_[1], tangent, normal, binormal),
                                motion3_picked(pick_[2], tangent, normal, binormal));
}

}  // namespace grape
