// Handles and storage: lookup, seek, kill, compaction after a dispatch, tick listeners.
#include "engine_impl.hpp"
#include "timeline_impl.hpp"

#include <grape/error.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace grape::detail {

const Hot* EngineImpl::find(std::uint32_t slot, std::uint32_t generation) const noexcept {
    if (slot >= slots_.size()) return nullptr;
    const Slot& s = slots_[slot];
    if (s.generation != generation || (s.dense & free_bit)) return nullptr;
    return &hot_[s.dense];
}

Animation EngineImpl::with_generation_for_test(const Animation& a, std::uint32_t generation) noexcept {
    const LiveRecord r = a.record();
    if (!r) return {};
    r.impl->slots_[a.slot_].generation = generation;
    return Animation(a.engine_, a.slot_, generation);
}

std::uint32_t EngineImpl::slot_for_test(const Animation& a) noexcept { return a.slot_; }

const Extra* EngineImpl::extra(std::uint32_t slot) const noexcept {
    const auto it = extras_.find(slot);
    return it == extras_.end() ? nullptr : &it->second;
}

Extra* EngineImpl::extra_mut(std::uint32_t slot) noexcept {
    const auto it = extras_.find(slot);
    return it == extras_.end() ? nullptr : &it->second;
}

Extra& EngineImpl::extra_for(std::uint32_t slot) { return extras_[slot]; }

void EngineImpl::seek(std::uint32_t dense, double seconds) noexcept {
    if (!std::isfinite(seconds)) return;
    Hot& h = hot_[dense];
    Cold& c = cold_[dense];
    const PlayState s = play_at_position(seconds / c.duration, static_cast<double>(c.plays()),
                                         c.reversed, (h.flags & flag_yoyo) != 0, gap_of(dense));
    c.set_play(s.finished ? c.plays() - 1 : wrap_plays(s.play));
    h.phase = s.phase + s.gap;
    h.flags = play_flags(h.flags, s.backward, c);
    try {
        Dispatch d(*this);
        write_state(dense);
    } catch (...) {  // a throwing on_update handler: the state is set; the error is dropped
    }
}

void EngineImpl::set_time_scale(std::uint32_t dense, double scale) noexcept {
    if (!(std::isfinite(scale) && scale >= 0.0)) return;
    const double rate = scale / cold_[dense].duration;
    if (!std::isfinite(rate)) return;  // an overflowing rate is ignored too
    hot_[dense].rate = hot_[dense].rate < 0.0 ? -rate : rate;  // keeps the direction
    remember_scale(cold_[dense].slot, scale);
}

void EngineImpl::mark_dead(std::uint32_t dense) noexcept {
    Hot& h = hot_[dense];
    if (h.flags & flag_dead) return;
    h.flags |= flag_dead;
    if (timelines_ && (h.flags & flag_paused)) timelines_->forget(cold_[dense].slot);
    ++slots_[cold_[dense].slot].generation;  // handles go inert now; storage goes later
    --live_;
    ++dead_;
}

void EngineImpl::kill(std::uint32_t dense) noexcept {
    mark_dead(dense);
    if (!ticking_ && depth_ == 0) finish_dispatch();
}

void EngineImpl::kill_all() noexcept {
    if (timelines_) timelines_->kill_all();
    for (std::uint32_t i = 0; i < hot_.size(); ++i) mark_dead(i);
    if (!ticking_ && depth_ == 0) finish_dispatch();
}

void EngineImpl::remove_now(std::uint32_t dense) noexcept {
    if (index_on_) index_erase(dense);
    const std::uint32_t slot = cold_[dense].slot;
    release_path(hot_[dense].path);
    release_curve(cold_[dense].curve);
    extras_.erase(slot);
    if (slots_[slot].generation == last_generation) {
        slots_[slot].dense = UINT32_MAX;  // retired: free (the high bit), on no chain, never reused
    } else {
        slots_[slot].dense = free_bit | (free_slot_ & ~free_bit);
        free_slot_ = slot;
    }
    const auto last = static_cast<std::uint32_t>(hot_.size() - 1);
    if (dense < driven_begin_) {  // the last ticked record fills the hole, the last record its place
        const std::uint32_t edge = driven_begin_ - 1;
        if (dense != edge) move_record(edge, dense);
        if (edge != last) move_record(last, edge);
        --driven_begin_;
    } else if (dense != last) {
        move_record(last, dense);
    }
    hot_.pop_back();
    cold_.pop_back();
}

void EngineImpl::move_record(std::uint32_t from, std::uint32_t to) noexcept {
    hot_[to] = hot_[from];
    cold_[to] = cold_[from];
    slots_[cold_[to].slot].dense = to;
}

void EngineImpl::make_driven(std::uint32_t dense) noexcept {
    if (dense >= driven_begin_) return;
    const std::uint32_t edge = driven_begin_ - 1;
    if (dense != edge) {
        std::swap(hot_[dense], hot_[edge]);
        std::swap(cold_[dense], cold_[edge]);
        slots_[cold_[dense].slot].dense = dense;
        slots_[cold_[edge].slot].dense = edge;
    }
    --driven_begin_;
}

void EngineImpl::compact() noexcept {
    for (std::uint32_t i = 0; i < hot_.size() && dead_ > 0;) {
        if (hot_[i].flags & flag_dead) {
            remove_now(i);  // the last record moves into i; look at i again
            --dead_;
        } else {
            ++i;
        }
    }
    dead_ = 0;
}

void EngineImpl::finish_dispatch() noexcept {
    if (timelines_) timelines_->finish();
    if (dead_ > 0) compact();
    if (listeners_removed_) {
        std::erase_if(listeners_, [](const Listener& l) { return l.removed; });
        std::erase_if(new_listeners_, [](const Listener& l) { return l.removed; });
        listeners_removed_ = false;
    }
    if (!new_listeners_.empty()) {
        try {
            for (Listener& l : new_listeners_) listeners_.push_back(std::move(l));
        } catch (...) {  // out of memory: listeners not yet joined are dropped
        }
        new_listeners_.clear();
    }
}

std::size_t EngineImpl::on_tick(std::function<void(double)> listener) {
    const std::size_t id = next_listener_++;
    if (ticking_ || depth_ > 0) new_listeners_.push_back({id, std::move(listener)});
    else listeners_.push_back({id, std::move(listener)});
    return id;
}

void EngineImpl::remove_tick_listener(std::size_t id) noexcept {
    for (auto* list : {&listeners_, &new_listeners_}) {
        for (Listener& l : *list) {
            if (l.id == id && !l.removed) {
                l.removed = true;  // not called again; erased once no listener is running
                listeners_removed_ = true;
                if (!ticking_ && depth_ == 0) finish_dispatch();
                return;
            }
        }
    }
}

std::size_t EngineImpl::storage_bytes() const noexcept {
    return hot_.capacity() * sizeof(Hot) + cold_.capacity() * sizeof(Cold) + slots_.capacity() * sizeof(Slot);
}

}  // namespace grape::detail
