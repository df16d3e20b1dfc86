// <windows.h> for grape's own sources, included once here the same way everywhere: without its
// min and max macros (they break std::min, std::max and numeric_limits<T>::max) and without the
// rarely used parts (sockets, cryptography, ...), which also keeps its parse time down.
#pragma once

#ifdef _WIN32
#ifndef NOMINMAX
#define NOMINMAX
#endif
#ifndef WIN32_LEAN_AND_MEAN
#define WIN32_LEAN_AND_MEAN
#endif
#include <windows.h>
#endif
