// The chain in Box2D v3: see bench_dynamics_box2d3.hpp.
#include "bench_dynamics_box2d3.hpp"

#include <box2d/box2d.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <vector>

namespace grape::bench {

namespace {
double thread_seconds() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}
}  // namespace

Box2d3Run box2d3_chain(std::size_t links, double link, double g, double frame, int frames, int substeps) {
    b2WorldDef world_def = b2DefaultWorldDef();
    world_def.gravity = {0.0f, static_cast<float>(-g)};
    world_def.enableSleep = false;  // the same work every frame, as grape does
    const b2WorldId world = b2CreateWorld(&world_def);
    b2BodyDef ground_def = b2DefaultBodyDef();
    std::vector<b2BodyId> bodies{b2CreateBody(world, &ground_def)};
    // Point masses like grape's particles: mass 1, no shape (nothing for the broad phase),
    // no rotational inertia (the joints act at the centers, so rotation plays no part).
    const b2MassData mass{.mass = 1.0f, .center = {0.0f, 0.0f}, .rotationalInertia = 0.0f};
    for (std::size_t k = 1; k <= links; ++k) {
        b2BodyDef def = b2DefaultBodyDef();
        def.type = b2_dynamicBody;
        def.position = {static_cast<float>(static_cast<double>(k) * link), 0.0f};
        const b2BodyId body = b2CreateBody(world, &def);
        b2Body_SetMassData(body, mass);
        b2DistanceJointDef joint = b2DefaultDistanceJointDef();
        joint.bodyIdA = bodies.back();
        joint.bodyIdB = body;
        joint.length = static_cast<float>(link);
        joint.enableSpring = false;  // rigid
        b2CreateDistanceJoint(world, &joint);
        bodies.push_back(body);
    }
    Box2d3Run run;
    std::vector<b2Vec2> x(bodies.size());
    for (int f = 0; f < frames; ++f) {
        const double start = thread_seconds();
        b2World_Step(world, static_cast<float>(frame), substeps);
        run.seconds += thread_seconds() - start;
        for (std::size_t k = 0; k < bodies.size(); ++k) x[k] = b2Body_GetPosition(bodies[k]);
        for (std::size_t k = 1; k < bodies.size(); ++k) {
            const double dx = static_cast<double>(x[k].x) - x[k - 1].x, dy = static_cast<double>(x[k].y) - x[k - 1].y;
            run.link_error = std::max(run.link_error, std::abs(std::hypot(dx, dy) - link));
        }
    }
    b2DestroyWorld(world);
    return run;
}

const char* box2d3_version() {
    static char text[32];
    const b2Version v = b2GetVersion();
    std::snprintf(text, sizeof text, "%d.%d.%d", v.major, v.minor, v.revision);
    return text;
}

}  // namespace grape::bench
