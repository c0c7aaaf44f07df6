// The entry point of every C++ test binary: `BINARY SUITE [ARGUMENTS...]` runs the registered
// suite SUITE (check.hpp's CHECK_SUITE) with the remaining arguments; a binary holding one suite
// also runs it without its name; `BINARY` alone runs every suite in turn; `BINARY --list` names them.
#include "check.hpp"

#include <cstdio>
#include <cstring>

int main(int argc, char** argv) {
  const std::vector<check::Suite>& suites = check::suites();
  if (argc > 1 && std::strcmp(argv[1], "--list") == 0) {
    for (const check::Suite& suite : suites) std::printf("%s\n", suite.name);
    return 0;
  }
  if (argc > 1) {
    for (const check::Suite& suite : suites)
      if (std::strcmp(argv[1], suite.name) == 0) return suite.main(argc - 1, argv + 1);
    if (suites.size() == 1) return suites.front().main(argc, argv);
    std::printf("no suite named %s in this binary (--list names them)\n", argv[1]);
    return 2;
  }
  int status = 0;
  for (const check::Suite& suite : suites) {
    check::passed = check::failed = 0;
    char* arguments[] = {const_cast<char*>(suite.name), nullptr};
    if (suite.main(1, arguments) != 0) status = 1;
  }
  return status;
}
