/// `lucent`: the command-line front end (cli/run.cpp).
#include "commands.hpp"

int main(int argc, char** argv) { return lucent::cli::run(argc, argv); }
