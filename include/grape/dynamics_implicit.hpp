// grape — dynamics: implicit curves C(x, y) = 0 that a particle is held on (by a
// ParticleSystem's curve constraint), with value, gradient and Hessian from the user or by
// automatic differentiation of one templated function (Jet2). Included by <grape/dynamics.hpp>.
#pragma once

#include <grape/error.hpp>
#include <grape/export_dynamics.hpp>
#include <grape/jet.hpp>
#include <grape/math.hpp>

#include <functional>

namespace grape {

/// \addtogroup dynamics
/// @{

// ---------------------------------------------------------------------------------------
// Implicit curves C(x, y) = 0
// ---------------------------------------------------------------------------------------

/// C and its first and second derivatives at one point.
struct ImplicitSample {
    double value = 0.0;  ///< C(x, y), in the curve's own units
    Vec2 gradient{};     ///< ∇C
    double hxx = 0.0;    ///< ∂²C/∂x²
    double hxy = 0.0;    ///< ∂²C/∂x∂y
    double hyy = 0.0;    ///< ∂²C/∂y²
};

/// A curve C(x, y) = 0 that a particle is held on. Value, gradient and Hessian come either
/// from the user or from one templated function differentiated automatically (Jet2).
class GRAPE_DYNAMICS_API ImplicitFunction {
public:
    /// User-supplied value, gradient and Hessian. Throws grape::Error if `evaluate` is empty.
    explicit ImplicitFunction(std::function<ImplicitSample(Vec2)> evaluate);

    /// From C written once for any number type: `[](auto x, auto y) { return x*x + 100*y; }`.
    /// Gradient and Hessian by forward-mode automatic differentiation.
    template <class F>
    static ImplicitFunction from_function(F function) {
        return ImplicitFunction(std::function<ImplicitSample(Vec2)>([function](Vec2 p) {
            const Jet2 c = function(Jet2::x(p.x), Jet2::y(p.y));
            return ImplicitSample{c.v, {c.gx, c.gy}, c.hxx, c.hxy, c.hyy};
        }));
    }

    /// C, ∇C and the Hessian at p.
    ImplicitSample operator()(Vec2 p) const { return evaluate_(p); }

private:
    std::function<ImplicitSample(Vec2)> evaluate_{};
};

/// @}

}  // namespace grape
