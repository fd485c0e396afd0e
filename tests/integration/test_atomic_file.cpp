// Outputs are written to a temporary file renamed into place: nothing half-written is left behind,
// also when SIGINT or SIGTERM ends the process in the middle of a write.
#include <doctest/doctest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <fstream>

#include "io/atomic_file.hpp"
#include "temp_dir.hpp"

namespace {
/// Forks a child that opens `path` through AtomicFile, writes its temporary and raises `sig`;
/// returns the child's wait status, with `temp` its temporary's name.
int interruptedWrite(const std::string& path, int sig, std::string& temp) {
  temp = path + ".tmp-";
  const pid_t child = ::fork();
  if (child == 0) {
    std::signal(SIGINT, SIG_DFL);  // as in the CLI (the test runner catches them)
    std::signal(SIGTERM, SIG_DFL);
    lucent::io::AtomicFile out(path);
    std::ofstream(out.tempPath()) << std::string(1 << 20, 'x');
    std::raise(sig);
    ::_exit(0);  // not reached: the signal ends the child
  }
  temp += std::to_string(child);
  int status = 0;
  ::waitpid(child, &status, 0);
  return status;
}
}  // namespace

TEST_CASE(
    "SIGINT or SIGTERM in the middle of a write leaves no temporary file, and still ends "
    "the process by that signal") {
  for (const int sig : {SIGINT, SIGTERM}) {
    lucent::test::TempDir dir;
    std::string temp;
    const int status = interruptedWrite(dir / "image.exr", sig, temp);
    CHECK(WIFSIGNALED(status));
    CHECK(WTERMSIG(status) == sig);
    CHECK_FALSE(std::filesystem::exists(temp));
    CHECK_FALSE(std::filesystem::exists(dir / "image.exr"));
  }
}

TEST_CASE("A committed write replaces the file, an abandoned one leaves the old file as it was") {
  lucent::test::TempDir dir;
  std::ofstream(dir / "a.txt") << "old";
  {
    lucent::io::AtomicFile out(dir / "a.txt");
    std::ofstream(out.tempPath()) << "abandoned";
  }
  CHECK(lucent::test::slurp(dir / "a.txt") == "old");
  lucent::io::writeTextFile(dir / "a.txt", "new");
  CHECK(lucent::test::slurp(dir / "a.txt") == "new");
  CHECK(std::distance(std::filesystem::directory_iterator(dir.path),
                      std::filesystem::directory_iterator()) == 1);
}
