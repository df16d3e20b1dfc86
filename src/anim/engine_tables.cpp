// The engine's shared tables: paths and curves, reference-counted, equal ones shared.
#include "engine_impl.hpp"

#include <grape/error.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace grape::detail {

std::uint32_t EngineImpl::acquire_path(const Path& path) {
    const void* shape = shape_id(path);
    if (auto it = path_index_.find(shape); it != path_index_.end()) {
        ++paths_[it->second].refs;
        return it->second;
    }
    PathEntry entry;
    entry.path = path;
    entry.shape = shape;
    entry.kernel = make_kernel(path);
    entry.refs = 1;
    PathFast fast;
    fast.fast = entry.kernel.kind;
    for (int k = 0; k < 4; ++k) fast.c[k] = entry.kernel.c[k];
    if (entry.kernel.table) {  // the table's buffer survives moving the entry
        fast.table = entry.kernel.table->values().data();
        fast.steps = entry.kernel.table->steps();
    }
    std::uint32_t index;
    if (!free_paths_.empty()) {
        index = free_paths_.back();
        free_paths_.pop_back();
        paths_[index] = std::move(entry);
        path_fast_[index] = fast;
        path_kind_[index] = fast.fast;
        line_fast_[index] = {{fast.c[0], fast.c[1]}};
        arc_fast_[index] = {fast.table, fast.steps};
    } else {
        index = static_cast<std::uint32_t>(paths_.size());
        paths_.push_back(std::move(entry));
        path_fast_.push_back(fast);
        path_kind_.push_back(fast.fast);
        line_fast_.push_back({{fast.c[0], fast.c[1]}});
        arc_fast_.push_back({fast.table, fast.steps});
        free_paths_.reserve(paths_.size());  // so releasing during a tick never allocates
    }
    path_index_.emplace(shape, index);
    return index;
}

void EngineImpl::release_path(std::uint32_t index) noexcept {
    PathEntry& e = paths_[index];
    if (--e.refs != 0) return;
    path_index_.erase(e.shape);
    e = PathEntry();                // drops the shape if nobody else holds it
    path_fast_[index] = PathFast();
    path_kind_[index] = KernelKind::generic;
    arc_fast_[index] = ArcFast();
    free_paths_.push_back(index);   // capacity reserved at creation
}

std::uint16_t EngineImpl::acquire_curve(const Curve& curve) {
    std::string key = to_string(curve);
    // A function curve has no text of its own: its shared callable is its identity (the
    // entry keeps that callable alive, so the address is not reused while the key exists).
    if (curve.kind() == CurveKind::function) key += '@' + std::to_string(reinterpret_cast<std::uintptr_t>(curve.identity()));
    if (auto it = curve_index_.find(key); it != curve_index_.end()) {
        ++curves_[it->second].refs;
        return it->second;
    }
    std::uint16_t index;
    if (!free_curves_.empty()) {
        index = free_curves_.back();
        free_curves_.pop_back();
        curves_[index] = {curve, 1, {}};
    } else {
        if (curves_.size() > std::numeric_limits<std::uint16_t>::max())
            throw Error("Engine: more than 65535 distinct curves with parameters alive at once");
        index = static_cast<std::uint16_t>(curves_.size());
        curves_.push_back({curve, 1, {}});
        free_curves_.reserve(curves_.size());  // so releasing during a tick never allocates
    }
    curves_[index].key = key;
    curve_index_.emplace(std::move(key), index);
    return index;
}

std::uint16_t EngineImpl::acquire_curve_for(std::uint32_t path, const Curve& curve) {
    if (!has_parameters(curve.kind())) return 0;  // evaluated by kind, no slot needed
    try {
        return acquire_curve(curve);
    } catch (...) {
        release_path(path);
        throw;
    }
}

void EngineImpl::release_curve(std::uint16_t index) noexcept {
    if (index == 0) return;
    CurveEntry& e = curves_[index];
    if (--e.refs != 0) return;
    curve_index_.erase(e.key);
    free_curves_.push_back(index);  // capacity reserved at creation
    e.curve = Curve();
    e.key.clear();
}

}  // namespace grape::detail
