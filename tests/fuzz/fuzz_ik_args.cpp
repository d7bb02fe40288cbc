// Fuzzes `kinema ik`'s argument vector the way the CLI parses it (CLI11 through
// addIkCommand, then runIk's own checks) on the default character saved as a .kinema file.
// The input is the arguments after the file, separated by NUL bytes. Whatever the
// arguments, the command must not crash, must return an exit code of the contract (0, 1
// or 2), and with --json and exit 0 must print JSON whose error and joint numbers are all
// finite (never null, JSON's stand-in for NaN and infinity).
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "cli/command_line.h"
#include "cli/ik_command.h"
#include "io/kinema_file.h"
#include "scene/default_character_scene.h"

namespace {

// The default character with its meshes dropped (IK reads the skeleton only; a small file).
std::string characterFile() {
  static const std::string path = [] {
    const std::string p = "/tmp/fuzz_ik_args_" + std::to_string(static_cast<long>(::getpid())) + ".kinema";
    kinema::Scene scene = kinema::makeDefaultCharacterScene();
    scene.meshes.clear();
    scene.meshInstances.clear();
    scene.skins.clear();
    scene.materials.clear();
    scene.images.clear();
    if (!kinema::saveKinemaFile(p, scene).empty()) std::abort();
    std::atexit([] { std::remove(("/tmp/fuzz_ik_args_" + std::to_string(static_cast<long>(::getpid())) + ".kinema").c_str()); });
    return p;
  }();
  return path;
}

bool allNumbersFinite(const nlohmann::json& j) {
  if (j.is_null()) return false;
  if (j.is_number_float()) return std::isfinite(j.get<double>());
  if (j.is_array() || j.is_object())
    for (const auto& v : j)
      if (!allNumbersFinite(v)) return false;
  return true;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, size_t size) {
  if (size > 4096) return 0;
  static const bool quiet = [] {
    if (!std::freopen("/dev/null", "w", stdout)) std::abort();  // the summary's printf
    return true;
  }();
  (void)quiet;
  std::vector<std::string> args{"kinema", "ik", characterFile()};
  std::string current;
  for (size_t i = 0; i < size; ++i) {
    if (data[i] == 0) {
      args.push_back(current);
      current.clear();
    } else {
      current += static_cast<char>(data[i]);
    }
  }
  if (!current.empty()) args.push_back(current);
  if (args.size() > 40) return 0;

  CLI::App app("kinema");
  app.require_subcommand(1);
  kinema::cli::IkOptions options;
  kinema::cli::addIkCommand(app, options);
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  std::ostringstream out, err;
  std::streambuf* oldOut = std::cout.rdbuf(out.rdbuf());
  std::streambuf* oldErr = std::cerr.rdbuf(err.rdbuf());
  int rc = 0;
  bool solved = false;
  try {
    app.parse(static_cast<int>(argv.size()), argv.data());
    rc = kinema::cli::runIk(options);
    solved = true;
  } catch (const CLI::CallForHelp&) {
    rc = kinema::cli::kExitOk;  // help printed, nothing solved
  } catch (const CLI::CallForAllHelp&) {
    rc = kinema::cli::kExitOk;
  } catch (const CLI::ParseError&) {
    rc = kinema::cli::kExitUsage;  // main prints CLI11's message and exits 2
  }
  std::cout.rdbuf(oldOut);
  std::cerr.rdbuf(oldErr);
  if (rc != kinema::cli::kExitOk && rc != kinema::cli::kExitBadInput && rc != kinema::cli::kExitUsage) {
    std::fprintf(stderr, "fuzz_ik_args: exit code %d\n", rc);
    std::abort();
  }
  if (solved && rc == kinema::cli::kExitOk && options.json) {
    const nlohmann::json j = nlohmann::json::parse(out.str(), nullptr, false);
    if (j.is_discarded() || !allNumbersFinite(j)) {
      std::fprintf(stderr, "fuzz_ik_args: exit 0 with non-finite JSON: %.300s\n", out.str().c_str());
      std::abort();
    }
  }
  return 0;
}
