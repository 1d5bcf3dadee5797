#include <cstdio>
int main() { std::puts("illum " ILLUM_VERSION); }
