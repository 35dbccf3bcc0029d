// amp: the command line of the Adaptive Motion Planning library.
#include <cstdio>

int main() { std::puts("amp"); return 0; }
