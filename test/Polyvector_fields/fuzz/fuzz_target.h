// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

// How one harness source becomes either a libFuzzer program or an entry of
// the corpus replay.
//
//   PVF_FUZZ_TARGET(constraints) { ... data, size ... }
//
// With PVF_FUZZ_LIBFUZZER defined (one harness per clang executable, built
// with -fsanitize=fuzzer) the body is LLVMFuzzerTestOneInput. Without it, the
// body is a function registered under its name in pvf_fuzz::targets(), and the
// replay program (fuzz_corpus_replay.cpp, a single translation unit that
// includes every harness) runs it on each file of corpus/<name>/.
//
// PVF_FUZZ_CHECK(condition, message) states a property of the package: it
// aborts under libFuzzer (a crash that libFuzzer saves) and throws
// pvf_fuzz::Check_failure in the replay (which reports the file and fails).

#ifndef CGAL_POLYVECTOR_FIELDS_TEST_FUZZ_TARGET_H
#define CGAL_POLYVECTOR_FIELDS_TEST_FUZZ_TARGET_H

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

namespace pvf_fuzz {

typedef void (*Target_function)(const std::uint8_t* data, std::size_t size);

struct Target
{
  const char* name;
  Target_function run;
};

// The harnesses of the replay, in registration order.
inline std::vector<Target>& targets()
{
  static std::vector<Target> list;
  return list;
}

struct Registrar
{
  Registrar(const char* name, Target_function run) { targets().push_back(Target{ name, run }); }
};

struct Check_failure : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

[[noreturn]] inline void check_failed(const char* condition, const std::string& message, const char* file, int line)
{
  const std::string what = std::string(file) + ":" + std::to_string(line) + ": check failed: " + condition +
                           (message.empty() ? std::string() : ": " + message);
#ifdef PVF_FUZZ_LIBFUZZER
  std::fprintf(stderr, "%s\n", what.c_str());
  std::fflush(stderr);
  std::abort();
#else
  throw Check_failure(what);
#endif
}

} // namespace pvf_fuzz

#define PVF_FUZZ_CHECK(condition, message)                                  \
  do                                                                        \
  {                                                                         \
    if(!(condition))                                                        \
      ::pvf_fuzz::check_failed(#condition, (message), __FILE__, __LINE__);  \
  } while(false)

#ifdef PVF_FUZZ_LIBFUZZER
#  define PVF_FUZZ_TARGET(name)                                                              \
    static void pvf_fuzz_target_##name(const std::uint8_t* data, std::size_t size);          \
    extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)        \
    {                                                                                        \
      pvf_fuzz_target_##name(data, size);                                                    \
      return 0;                                                                              \
    }                                                                                        \
    static void pvf_fuzz_target_##name(const std::uint8_t* data, std::size_t size)
#else
#  define PVF_FUZZ_TARGET(name)                                                              \
    static void pvf_fuzz_target_##name(const std::uint8_t* data, std::size_t size);          \
    static const ::pvf_fuzz::Registrar pvf_fuzz_registrar_##name(#name, &pvf_fuzz_target_##name); \
    static void pvf_fuzz_target_##name(const std::uint8_t* data, std::size_t size)
#endif

#endif // CGAL_POLYVECTOR_FIELDS_TEST_FUZZ_TARGET_H
