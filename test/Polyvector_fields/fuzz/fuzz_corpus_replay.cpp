// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

// The corpus replay: every harness in one translation unit (each TU with CGAL
// costs ~30 s to compile), run on every file of corpus/<target>/.
//
//   fuzz_corpus_replay [--in-process] CORPUS_DIR              every target on its folder
//   fuzz_corpus_replay [--in-process] --target NAME FILE...   one target on some files
//   fuzz_corpus_replay --list                                 the target names
//
// On POSIX each input runs in a child process (unless --in-process), so that
// a crash (signal) or a hang (more than 20 s) on one file is reported with its
// name and the other files still run. Fails (exit 1) when a harness check
// fails, an exception escapes, an input crashes or hangs, a target has no
// corpus folder or an empty one, or a corpus folder names no target. Inputs
// slower than a second are reported (not failed: the machine may be busy).

#include "fuzz_constraints.cpp"
#include "fuzz_dmat.cpp"
#include "fuzz_rawfield.cpp"
#include "fuzz_singularities.cpp"
#include "fuzz_off_mesh.cpp"
#include "fuzz_obj_mesh.cpp"
#include "fuzz_design.cpp"
#include "fuzz_meshing.cpp"
#include "fuzz_quad_map.cpp"
#include "fuzz_planarize.cpp"

#include <algorithm>
#include <chrono>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <memory>
#include <set>
#include <string>
#include <vector>

#if defined(__unix__) || defined(__APPLE__)
#  include <csignal>
#  include <sys/types.h>
#  include <sys/wait.h>
#  include <unistd.h>
#  define PVF_FUZZ_REPLAY_HAS_FORK 1
#else
#  define PVF_FUZZ_REPLAY_HAS_FORK 0
#endif

namespace {

namespace fs = std::filesystem;

const pvf_fuzz::Target* find_target(const std::string& name)
{
  for(const pvf_fuzz::Target& t : pvf_fuzz::targets())
    if(name == t.name)
      return &t;
  return nullptr;
}

bool read_file(const fs::path& path, std::vector<std::uint8_t>& bytes)
{
  std::ifstream in(path, std::ios::binary);
  if(!in)
    return false;
  bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  return !in.bad();
}

struct Tally
{
  std::size_t passed = 0, failed = 0;
};

// Runs `target` on `bytes` in this process; returns the failure, or an empty string.
std::string run_here(const pvf_fuzz::Target& target, const std::vector<std::uint8_t>& bytes)
{
  // A copy of exactly the input's size, so that a read past its end is caught
  // by a sanitizer, as under libFuzzer.
  std::unique_ptr<std::uint8_t[]> copy(new std::uint8_t[bytes.size() + (bytes.empty() ? 1 : 0)]);
  if(!bytes.empty())
    std::memcpy(copy.get(), bytes.data(), bytes.size());
  try
  {
    target.run(copy.get(), bytes.size());
  }
  catch(const std::exception& e)
  {
    return std::string("exception: ") + e.what();
  }
  catch(...)
  {
    return "an exception of unknown type";
  }
  return std::string();
}

// Seconds after which an input counts as a hang (only with a child process per input).
const unsigned hang_seconds = 20;
bool fork_per_input = true;

// Runs `target` on the file `path`; reports a failure on std::cerr. With
// fork_per_input (POSIX), each input runs in a child process, so that a crash
// or a hang on one file is reported as such and the other files still run.
void replay(const pvf_fuzz::Target& target, const fs::path& path, Tally& tally)
{
  std::vector<std::uint8_t> bytes;
  if(!read_file(path, bytes))
  {
    std::cerr << "FAILED " << target.name << " " << path.string() << ": cannot read the file\n";
    ++tally.failed;
    return;
  }
  const auto start = std::chrono::steady_clock::now();
  std::string failure;
#if PVF_FUZZ_REPLAY_HAS_FORK
  if(fork_per_input)
  {
    std::cout.flush();
    std::cerr.flush();
    const pid_t child = ::fork();
    if(child == 0)
    {
      ::alarm(hang_seconds);
      const std::string message = run_here(target, bytes);
      if(!message.empty())
        std::cerr << "FAILED " << target.name << " " << path.string() << ": " << message << std::endl;
      std::_Exit(message.empty() ? 0 : 1);
    }
    int status = 0;
    if(child < 0 || ::waitpid(child, &status, 0) != child)
      failure = "cannot run a child process";
    else if(WIFEXITED(status) && WEXITSTATUS(status) == 1)
    {
      ++tally.failed;  // the child said why
      return;
    }
    else if(WIFSIGNALED(status) && WTERMSIG(status) == SIGALRM)
      failure = "a hang: still running after " + std::to_string(hang_seconds) + " s";
    else if(WIFSIGNALED(status))
      failure = "a crash: killed by signal " + std::to_string(WTERMSIG(status)) + " (" + ::strsignal(WTERMSIG(status)) + ")";
    else if(!WIFEXITED(status) || WEXITSTATUS(status) != 0)
      failure = "exit status " + std::to_string(WEXITSTATUS(status));
  }
  else
#endif
    failure = run_here(target, bytes);
  if(!failure.empty())
  {
    std::cerr << "FAILED " << target.name << " " << path.string() << ": " << failure << "\n";
    ++tally.failed;
    return;
  }
  ++tally.passed;
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if(seconds > 1.0)
    std::cerr << "SLOW " << target.name << " " << path.string() << ": " << seconds << " s (more than 1 s)\n";
}

int usage()
{
  std::cerr << "usage: fuzz_corpus_replay [--in-process] CORPUS_DIR\n"
               "       fuzz_corpus_replay [--in-process] --target NAME FILE...\n"
               "       fuzz_corpus_replay --list\n";
  return 2;
}

} // namespace

int main(int argc, char** argv)
{
  if(argc >= 2 && std::strcmp(argv[1], "--in-process") == 0)
  {
    fork_per_input = false;
    --argc;
    ++argv;
  }
  if(argc == 2 && std::strcmp(argv[1], "--list") == 0)
  {
    for(const pvf_fuzz::Target& t : pvf_fuzz::targets())
      std::cout << t.name << "\n";
    return 0;
  }
  Tally tally;
  if(argc >= 3 && std::strcmp(argv[1], "--target") == 0)
  {
    const pvf_fuzz::Target* target = find_target(argv[2]);
    if(target == nullptr)
    {
      std::cerr << "no fuzz target '" << argv[2] << "' (see --list)\n";
      return 2;
    }
    for(int i = 3; i < argc; ++i)
      replay(*target, argv[i], tally);
  }
  else if(argc == 2)
  {
    const fs::path root = argv[1];
    std::error_code ec;
    if(!fs::is_directory(root, ec))
    {
      std::cerr << "FAILED: '" << root.string() << "' is not a folder\n";
      return 1;
    }
    std::set<std::string> folders;
    for(const auto& entry : fs::directory_iterator(root))
      if(entry.is_directory())
        folders.insert(entry.path().filename().string());
    for(const std::string& name : folders)
      if(find_target(name) == nullptr)
      {
        std::cerr << "FAILED: the corpus folder '" << name << "' names no fuzz target\n";
        ++tally.failed;
      }
    for(const pvf_fuzz::Target& target : pvf_fuzz::targets())
    {
      std::vector<fs::path> files;
      if(folders.count(target.name))
        for(const auto& entry : fs::directory_iterator(root / target.name))
          if(entry.is_regular_file())
            files.push_back(entry.path());
      std::sort(files.begin(), files.end());
      if(files.empty())
      {
        std::cerr << "FAILED " << target.name << ": no corpus file in " << (root / target.name).string() << "\n";
        ++tally.failed;
        continue;
      }
      const Tally before = tally;
      const auto start = std::chrono::steady_clock::now();
      for(const fs::path& file : files)
        replay(target, file, tally);
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      std::cout << target.name << ": " << files.size() << " files, " << (tally.failed - before.failed) << " failed, "
                << seconds << " s\n";
    }
  }
  else
    return usage();
  std::cout << tally.passed << " passed, " << tally.failed << " failed\n";
  return tally.failed == 0 ? 0 : 1;
}
