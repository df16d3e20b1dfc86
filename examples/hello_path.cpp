#include <grape/path.hpp>
int main() { return 0; }
