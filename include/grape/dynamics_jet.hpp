// grape — dynamics: Jet2 now lives in math, <grape/jet.hpp>; this header forwards to it
// so existing includes keep working.
#pragma once

#include <grape/jet.hpp>
