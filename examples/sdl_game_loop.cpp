// A first animation in an SDL2 game loop: a square rides a Bézier with quad-in-out, back and
// forth forever; Space pauses it, Escape quits. `sdl_game_loop --frames N` runs N frames of
// exactly 1/60 s and exits, so it runs headless (SDL_VIDEODRIVER=dummy) as a test.
#include <grape/anim.hpp>
#include <grape/bits.hpp>

#include <SDL.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>

struct Square {
    double x = 0, y = 0;
};

int main(int argc, char* argv[]) {
    const int frames = argc == 3 && std::strcmp(argv[1], "--frames") == 0 ? std::atoi(argv[2]) : -1;
    if (SDL_Init(SDL_INIT_VIDEO) != 0) return std::fprintf(stderr, "SDL_Init: %s\n", SDL_GetError()), 1;
    SDL_Window* window = SDL_CreateWindow("grape", SDL_WINDOWPOS_UNDEFINED, SDL_WINDOWPOS_UNDEFINED, 640, 480, 0);
    SDL_Renderer* renderer = window ? SDL_CreateRenderer(window, -1, SDL_RENDERER_SOFTWARE) : nullptr;
    if (!renderer) return std::fprintf(stderr, "SDL: %s\n", SDL_GetError()), 1;

    grape::Engine engine;
    grape::KeyState keys;
    Square square;
    const grape::CubicBezierPath path({40, 400}, {160, 40}, {480, 440}, {600, 80});
    const grape::Animation ride = engine.create_2d_animation(
        square, path, 1.5, {.curve = grape::Curve::quad_in_out(), .repeat = -1, .yoyo = true});

    Uint64 last = SDL_GetPerformanceCounter();
    bool running = true;
    for (int frame = 0; running && frame != frames; ++frame) {
        for (SDL_Event e; SDL_PollEvent(&e);) {
            if (e.type == SDL_QUIT) running = false;
            if (e.type == SDL_KEYDOWN && !e.key.repeat) keys.press(e.key.keysym.scancode);
            if (e.type == SDL_KEYUP) keys.release(e.key.keysym.scancode);
        }
        if (keys.pressed_this_frame(SDL_SCANCODE_ESCAPE)) running = false;
        if (keys.pressed_this_frame(SDL_SCANCODE_SPACE)) ride.paused() ? ride.resume() : ride.pause();

        const Uint64 now = SDL_GetPerformanceCounter();
        const double dt = frames >= 0 ? 1.0 / 60 : double(now - last) / double(SDL_GetPerformanceFrequency());
        last = now;
        engine.tick(dt);  // writes square.x, square.y
        keys.end_frame(dt);

        SDL_SetRenderDrawColor(renderer, 24, 24, 32, 255);
        SDL_RenderClear(renderer);
        SDL_SetRenderDrawColor(renderer, 120, 60, 160, 255);
        const SDL_Rect r{int(square.x) - 10, int(square.y) - 10, 20, 20};
        SDL_RenderFillRect(renderer, &r);
        SDL_RenderPresent(renderer);
        if (frames < 0) SDL_Delay(1);  // a real game waits for vsync here
    }
    SDL_DestroyRenderer(renderer);
    SDL_DestroyWindow(window);
    SDL_Quit();

    // 90 frames are 1.5 s: the first play has ended exactly at the path's end.
    const grape::Vec2 end = path.point(1.0);
    std::printf("square at (%.3f, %.3f)\n", square.x, square.y);
    return frames != 90 || (std::abs(square.x - end.x) < 1e-9 && std::abs(square.y - end.y) < 1e-9) ? 0 : 1;
}
