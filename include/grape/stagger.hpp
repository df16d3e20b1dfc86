// grape — stagger: the start offsets of N animations that begin one after another, spread
// like GSAP's stagger object (each / amount, from, grid, axis, ease), as a pure function.
//
//   auto delays = grape::stagger_offsets(5, {.each = 0.1, .from = grape::StaggerFrom::center});
//   // {0.4, 0.2, 0, 0.2, 0.4}
//   std::vector<grape::Animation> dots = grape::stagger(dots_count, {.amount = 1.0}, [&](std::size_t i, double delay) {
//       return engine.create_2d_animation(dot[i], path, 0.5, {.delay = delay});
//   });
//
// The rule (GSAP's `distribute`, in seconds): item j sits at column j % C and row j / C of a
// grid of C columns (without a grid: one row, C = count). Its distance d_j to the origin is
// measured in cells, in 2-D (or along one axis), from an origin: the corner half a cell
// before the first item (start, random), half a cell past the last (end), the center of the
// row or grid (center, edges), or the index item's cell (index). With
// the normalized distance n_j = (d_j − min d) / (max d − min d) (0 when all are equal) and the
// total spread V (`amount`, or `each` × (count − 1) without a grid; GSAP's each × max(C, count / C)
// with one, × count / C along y, × C along x), item j starts at V·curve(n_j). So `each` is
// the time between neighbours from the start or the end; from the center the outermost items
// start each × (count − 1) after the middle one, as in GSAP. `edges`, and a negative V, start
// item j at |V|·curve(1 − n_j): the farthest first.
// `random` gives the offsets of a corner origin in a shuffled order: a permutation of what `start`
// gives, the same for the same seed on every platform (SplitMix64 and Fisher–Yates).
#pragma once

#include <grape/curve.hpp>
#include <grape/export_anim.hpp>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <type_traits>
#include <utility>
#include <vector>

namespace grape {

/// \addtogroup stagger
/// @{

/// Where the stagger begins.
enum class StaggerFrom : std::uint8_t {
    start,   ///< the first item first
    end,     ///< the last item first
    center,  ///< the middle first (a row's center, or the grid's), outwards
    edges,   ///< the outermost first, inwards
    index,   ///< StaggerDef::index first, outwards from it
    random,  ///< a seeded random order (StaggerDef::seed)
};

/// Which distance orders the items of a grid.
enum class StaggerAxis : std::uint8_t {
    both,  ///< straight-line distance in cells
    x,     ///< columns only: each column starts together
    y,     ///< rows only: each row starts together
};

/// Items laid out row by row in `columns` columns (0: no grid, one row).
struct StaggerGrid {
    std::size_t columns = 0;  ///< items per row
    std::size_t rows = 0;     ///< 0: as many as the items need; else ≥ that (center of the grid)
};

/// A stagger; fill with designated initializers: `{.each = 0.1, .from = StaggerFrom::center}`.
/// Give `each` or `amount` (neither: all offsets 0; both: an error).
struct StaggerDef {
    std::optional<double> each{};  ///< seconds between neighbours (see the rule above); finite
    std::optional<double> amount{};  ///< seconds from the first start to the last; finite
    StaggerFrom from = StaggerFrom::start;  ///< which item starts first
    std::size_t index = 0;         ///< the item that starts first, for from = index (< count)
    std::uint64_t seed = 0;        ///< the order for from = random
    StaggerGrid grid{};            ///< 2-D distances on a grid
    StaggerAxis axis = StaggerAxis::both;  ///< which distance orders a grid's items
    Curve curve{};                 ///< distributes the offsets over the spread (GSAP's stagger ease)
};

/// Writes the start offset (seconds) of each of out.size() items. Throws grape::Error naming
/// the field for a bad def (both each and amount, non-finite values, an index past the items,
/// a grid smaller than the items). Allocates nothing.
GRAPE_ANIM_API void stagger_offsets(const StaggerDef& def, std::span<double> out);

/// The start offsets of `count` items.
GRAPE_ANIM_API std::vector<double> stagger_offsets(std::size_t count, const StaggerDef& def);

/// One call, N animations: calls `make(i, delay)` for i = 0 … count − 1 with the item's
/// offset and returns what it returns (Animation handles, or any other handle), in order.
template <class Make>
auto stagger(std::size_t count, const StaggerDef& def, Make&& make)
    -> std::vector<std::invoke_result_t<Make&, std::size_t, double>> {
    const std::vector<double> offsets = stagger_offsets(count, def);
    std::vector<std::invoke_result_t<Make&, std::size_t, double>> made;
    made.reserve(count);
    for (std::size_t i = 0; i < count; ++i) made.push_back(make(i, offsets[i]));
    return made;
}

/// @}

}  // namespace grape
