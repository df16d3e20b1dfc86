// Your own callable as a curve.
#include "curve_data.hpp"

#include <grape/curve.hpp>
#include <grape/error.hpp>

#include <cmath>
#include <memory>
#include <string>
#include <utility>

namespace grape {

namespace detail {

double function_eval(const CurveData& base, double t) noexcept {
    const auto& d = static_cast<const FunctionData&>(base);
    if (std::isnan(t)) return t;
    const double v = d.f(t);
    if (std::isfinite(v)) return v;
    return t < 0.5 ? d.at0 : d.at1;  // never hand a NaN or infinity to a path
}

}  // namespace detail

Curve Curve::from_function(std::function<double(double)> f) {
    if (!f) throw Error("Curve::from_function: the function is empty");
    auto data = std::make_shared<detail::FunctionData>();
    data->at0 = f(0.0);
    data->at1 = f(1.0);
    if (!std::isfinite(data->at0) || !std::isfinite(data->at1))
        throw Error(std::string("Curve::from_function: f(0) and f(1) must be finite (got ") + detail::number_text(data->at0) +
                    " and " + detail::number_text(data->at1) + ")");
    data->f = std::move(f);
    Curve c;
    c.kind_ = CurveKind::function;
    c.data_ = std::move(data);
    return c;
}

}  // namespace grape
