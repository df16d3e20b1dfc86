// Curves for JavaScript, by name both ways: Curve.parse("quad-in-out").at(0.25) === 0.125.
#include "web_util.hpp"

#include <grape/curve.hpp>

#include <emscripten/bind.h>

#include <string>

namespace grape::web {
namespace {

Curve parse(std::string name) { return parse_curve(name); }
double at(const Curve& c, double t) { return c(t); }
// Many t in, as many progress values out (one call per plot or table).
val at_many(const Curve& c, val ts) {
    std::vector<double> t = numbers(ts);
    for (double& x : t) x = c(x);
    return float64_array(t.data(), t.size());
}
std::string name(const Curve& c) { return to_string(c); }
std::string kind(const Curve& c) { return std::string(to_string(c.kind())); }
double ease(std::string name, double t) { return parse_curve(name)(t); }
val names() {
    val out = val::array();
    for (std::string_view n : curve_names()) out.call<void>("push", std::string(n));
    return out;
}
bool equals(const Curve& a, const Curve& b) { return a == b; }
double settling_time(const Curve& c) { return c.settling_time(); }
Curve svg(std::string data) { return Curve::svg(data); }
// Every number given (embind checks the count); parse("spring(170,26)") takes the defaults.
Curve spring(double stiffness, double damping, double mass, double velocity) {
    return Curve::spring({.stiffness = stiffness, .damping = damping, .mass = mass, .velocity = velocity});
}
Curve spring_duration(double duration, double bounce, double velocity) {
    return Curve::spring_duration(duration, bounce, velocity);
}

}  // namespace

EMSCRIPTEN_BINDINGS(grape_curve) {
    using namespace emscripten;
    class_<Curve>("Curve")
        .constructor<>()
        .function("at", &at)
        .function("atMany", guarded<&at_many>)
        .function("name", &name)
        .function("kind", &kind)
        .function("equals", &equals)
        .function("settlingTime", &settling_time)
        .class_function("parse", guarded<&parse>)
        .class_function("svg", guarded<&svg>)
        .class_function("spring", guarded<&spring>)
        .class_function("springDuration", guarded<&spring_duration>);
    function("parseCurve", guarded<&parse>);
    function("ease", guarded<&ease>);
    function("curveNames", &names);
}

}  // namespace grape::web
