#include "app/cli.h"
#include <cstdio>
namespace coilsim {
int runCli(int, char**) { std::puts("coilsim"); return 0; }
}
