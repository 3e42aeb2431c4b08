#include "app/cli.h"

int main(int argc, char** argv) { return coilsim::runCli(argc, argv); }
