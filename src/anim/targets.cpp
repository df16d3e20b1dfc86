// Safe targets: linked targets followed at every write, the first play's start (captures and
// overwrite), and the target index (written bytes -> records) behind kill_animations_of,
// animations_of and overwrite.
//
// The index is off until first needed, so engines that never ask pay nothing; turning it on
// walks the records once. It keys each record by the lowest byte it writes; a query for the
// bytes [lo, hi) looks at keys from lo − widest_ (the widest record indexed) to hi and checks
// each candidate's members, so its cost is the records near the object, not all of them.
#include "engine_impl.hpp"
#include "engine_3d.hpp"

#include <grape/error.hpp>

#include <algorithm>
#include <cstdint>
#include <vector>

namespace grape::detail {

bool EngineImpl::begin_write(std::uint32_t dense, Extra& e, double u) {
    Hot& h = hot_[dense];
    if (e.ref) {
        void* now = e.ref->get();
        if (!now) {  // the target is gone: stop without writing or firing anything
            kill(dense);
            return false;
        }
        char* at = static_cast<char*>(now) + e.target_offset;
        if (at != h.target) {  // moved (a vector that grew): write there, and find it there
            if (index_on_) index_erase(dense);
            h.target = at;
            if (index_on_) index_insert(dense);
        }
    }
    if (!e.started) start_play(dense);
    if (e.value) {
        if (h.target) e.value->write(h.target, u);
        return false;
    }
    return true;
}

void EngineImpl::start_play(std::uint32_t dense) {
    const auto it = extras_.find(cold_[dense].slot);
    if (it == extras_.end() || it->second.started) return;
    Extra& e = it->second;
    e.started = true;
    if (e.overwrite) overwrite_others(dense);  // first, so a captured start is what they left
    if (e.value && hot_[dense].target) e.value->start(hot_[dense].target);
}

// --- what a record writes ----------------------------------------------------------------------

template <class F>
void EngineImpl::members_of(std::uint32_t dense, F&& f) const noexcept {
    const Hot& h = hot_[dense];
    if (!h.target) return;
    const Extra* e = (h.flags & flag_custom) ? extra(cold_[dense].slot) : nullptr;
    if (e && e->value) {
        f(h.target + e->value->offset, e->value->size);
    } else if (e && e->p3) {
        const Layout3& l = e->p3->layout;
        const std::size_t bytes = l.is_float ? sizeof(float) : sizeof(double);
        f(h.target + l.x, bytes);
        f(h.target + l.y, bytes);
        f(h.target + l.z, bytes);
        if (e->p3->align != Align3::none) {
            if (l.member == Orient3Member::frame) f(h.target + l.orientation, sizeof(Frame3));
            else if (l.member == Orient3Member::basis) f(h.target + l.orientation, sizeof(Basis));
            else if (l.member == Orient3Member::quat) f(h.target + l.orientation, sizeof(Quat));
        }
    } else if (e && e->nd) {
        for (const MemberRef& m : e->members) f(h.target + m.offset, m.is_float ? sizeof(float) : sizeof(double));
    } else {
        const std::size_t bytes = (h.flags & flag_float) ? sizeof(float) : sizeof(double);
        f(h.target, bytes);
        f(h.target + h.y_offset, bytes);
        if (e && e->write_rotation) f(h.target + e->rotation_offset, e->rotation_float ? sizeof(float) : sizeof(double));
    }
}

EngineImpl::Span EngineImpl::span_of(std::uint32_t dense) const noexcept {
    Span s;
    members_of(dense, [&](const char* at, std::size_t bytes) {
        const auto lo = reinterpret_cast<std::uintptr_t>(at);
        if (s.hi == 0 || lo < s.lo) s.lo = lo;
        s.hi = std::max(s.hi, lo + bytes);
    });
    return s;
}

bool EngineImpl::writes_in(std::uint32_t dense, std::uintptr_t lo, std::uintptr_t hi) const noexcept {
    bool hit = false;
    members_of(dense, [&](const char* at, std::size_t bytes) {
        const auto a = reinterpret_cast<std::uintptr_t>(at);
        hit = hit || (a < hi && a + bytes > lo);
    });
    return hit;
}

// --- the index ---------------------------------------------------------------------------------

void EngineImpl::index_insert(std::uint32_t dense) {
    const std::uint32_t slot = cold_[dense].slot;
    Extra* e = (hot_[dense].flags & flag_custom) ? &extras_.find(slot)->second : nullptr;
    if (e && e->ref) linked_.insert(slot);
    const Span s = span_of(dense);
    if (s.hi == 0) return;
    by_address_.emplace(s.lo, slot);
    widest_ = std::max(widest_, static_cast<std::size_t>(s.hi - s.lo));
    if (e) e->indexed_at = s.lo;
}

void EngineImpl::index_erase(std::uint32_t dense) noexcept {
    const std::uint32_t slot = cold_[dense].slot;
    const auto it = (hot_[dense].flags & flag_custom) ? extras_.find(slot) : extras_.end();
    Extra* e = it == extras_.end() ? nullptr : &it->second;
    const Span s = span_of(dense);
    const std::uintptr_t key = e ? e->indexed_at : s.lo;  // plain records never move
    if (e && e->ref) linked_.erase(slot);
    if (e ? e->indexed_at == 0 : s.hi == 0) return;
    auto [first, last] = by_address_.equal_range(key);
    for (; first != last; ++first) {
        if (first->second == slot) {
            by_address_.erase(first);
            break;
        }
    }
    if (e) e->indexed_at = 0;
}

void EngineImpl::enable_index() {
    if (index_on_) return;
    for (std::uint32_t i = 0; i < hot_.size(); ++i) {
        if (!(hot_[i].flags & flag_dead)) index_insert(i);
    }
    index_on_ = true;
}

// Linked records are keyed where they were last written; before a query they are looked up
// again (one get() per linked record), so a vector that grew since is found where it is now.
void EngineImpl::refresh_linked() {
    for (const std::uint32_t slot : std::vector<std::uint32_t>(linked_.begin(), linked_.end())) {
        const std::uint32_t dense = slots_[slot].dense;
        if (dense & free_bit) continue;
        Hot& h = hot_[dense];
        if (h.flags & flag_dead) continue;
        Extra& e = extras_.find(slot)->second;
        void* now = e.ref->get();
        char* at = now ? static_cast<char*>(now) + e.target_offset : nullptr;
        if (at && at != h.target) {
            index_erase(dense);
            h.target = at;
            index_insert(dense);
        }
    }
}

template <class F>
void EngineImpl::for_each_in(std::uintptr_t lo, std::uintptr_t hi, F&& f) {
    // Keys are lowest bytes: a record reaching into [lo, hi) starts at or after lo − widest_.
    const std::uintptr_t from = lo > widest_ ? lo - widest_ : 0;
    std::vector<std::uint32_t> hits;
    for (auto it = by_address_.lower_bound(from); it != by_address_.end() && it->first < hi; ++it) {
        const std::uint32_t dense = slots_[it->second].dense;
        if (!(dense & free_bit) && !(hot_[dense].flags & flag_dead) && writes_in(dense, lo, hi)) hits.push_back(it->second);
    }
    for (const std::uint32_t slot : hits) f(slot);  // f may kill: the index is left alone meanwhile
}

std::size_t EngineImpl::kill_in(std::uintptr_t lo, std::uintptr_t hi) {
    enable_index();
    refresh_linked();
    std::size_t killed = 0;
    {
        Dispatch d(*this);  // removals wait until every record has been looked at
        for_each_in(lo, hi, [&](std::uint32_t slot) {
            const std::uint32_t dense = slots_[slot].dense;
            if ((dense & free_bit) || (hot_[dense].flags & flag_dead)) return;
            mark_dead(dense);
            ++killed;
        });
    }
    return killed;
}

std::vector<Animation> EngineImpl::find_in(std::uintptr_t lo, std::uintptr_t hi) {
    enable_index();
    refresh_linked();
    std::vector<Animation> found;
    for_each_in(lo, hi, [&](std::uint32_t slot) { found.push_back(Animation(owner_, slot, slots_[slot].generation)); });
    return found;
}

void EngineImpl::overwrite_others(std::uint32_t dense) {
    enable_index();
    const std::uint32_t self = cold_[dense].slot;
    const Span s = span_of(dense);
    if (s.hi == 0) return;
    for_each_in(s.lo, s.hi, [&](std::uint32_t slot) {
        const std::uint32_t other = slots_[slot].dense;
        if (slot == self || (other & free_bit) || (hot_[other].flags & flag_dead)) return;
        if (hot_[other].phase < 0.0) return;  // not started: it overwrites in turn when it starts
        // A record writing any byte this one writes goes whole (a 2-D record that shares only x
        // with this one included).
        bool overlaps = false;
        members_of(dense, [&](const char* at, std::size_t bytes) {
            const auto a = reinterpret_cast<std::uintptr_t>(at);
            overlaps = overlaps || writes_in(other, a, a + bytes);
        });
        if (overlaps) mark_dead(other);
    });
}

}  // namespace grape::detail
