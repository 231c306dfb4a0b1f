// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_IO_INTERNAL_ATOMIC_FILE_H
#define CGAL_POLYVECTOR_FIELDS_IO_INTERNAL_ATOMIC_FILE_H

// All-or-nothing file output.
//
// The writers of this package first build the whole content of a file in
// memory (and validate their input while doing so), then hand it to
// `write_file_atomically`, which writes a temporary file next to the
// destination and renames it over the destination once every byte is on
// disk. Whatever fails, the destination is either the old file (or absent) or
// the complete new file, never a part of it, and no temporary is left behind.

#include <CGAL/Polyvector_fields/Error_code.h>

#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstddef>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <ostream>
#include <random>
#include <string>
#include <system_error>
#include <thread>

namespace CGAL {
namespace Polyvector_fields {
namespace IO {
namespace internal {

// Returns a hard-to-guess suffix for a temporary file name.
inline std::string temporary_suffix(unsigned attempt)
{
  static std::atomic<unsigned long long> counter{ 0 };
  unsigned long long seed = counter.fetch_add(1) * 0x9E3779B97F4A7C15ULL + attempt;
  seed ^= static_cast<unsigned long long>(
            std::chrono::steady_clock::now().time_since_epoch().count());
  seed ^= static_cast<unsigned long long>(std::hash<std::thread::id>()(std::this_thread::get_id())) << 1;
  try
  {
    std::random_device device;
    seed ^= (static_cast<unsigned long long>(device()) << 32) ^ device();
  }
  catch(...)
  {
    // no random device: the counter, the clock and the thread id remain
  }
  static const char digits[] = "0123456789abcdefghijklmnopqrstuvwxyz";
  std::string suffix;
  for(int i = 0; i < 12; ++i)
  {
    suffix += digits[seed % 36];
    seed /= 36;
    if(seed == 0)
      seed = 0x5851F42D4C957F2DULL + unsigned(i) + attempt;
  }
  return suffix;
}

// Writes the text that `produce(sink)` gives, in chunks, to `filename` all
// at once: the destination is replaced by a complete file or left as it was.
// `produce` calls `sink(const char* data, std::size_t size)`, which returns
// false once writing failed, and returns false itself if it stopped. Returns
// CANNOT_OPEN_FILE on any failure (no directory, no permission, disk full,
// destination is a directory, ...).
template <typename Produce>
Error_code write_file_atomically_with(const std::string& filename, Produce&& produce)
{
  namespace fs = std::filesystem;
  if(filename.empty())
    return Error_code::CANNOT_OPEN_FILE;
  const fs::path destination(filename);
  if(!destination.has_filename())
    return Error_code::CANNOT_OPEN_FILE;
  std::error_code ec;
  if(fs::is_directory(destination, ec))
    return Error_code::CANNOT_OPEN_FILE;

  // Create a fresh temporary file in the destination's directory, so that the
  // final rename does not cross file systems. "x" refuses an existing file.
  fs::path temporary;
  std::FILE* file = nullptr;
  for(unsigned attempt = 0; attempt < 16 && file == nullptr; ++attempt)
  {
    temporary = destination;
    temporary.replace_filename("." + destination.filename().string() + ".tmp-" + temporary_suffix(attempt));
    errno = 0;
    file = std::fopen(temporary.string().c_str(), "wbx");
    if(file == nullptr && errno != EEXIST)
      return Error_code::CANNOT_OPEN_FILE;
  }
  if(file == nullptr)
    return Error_code::CANNOT_OPEN_FILE;

  bool written = true;
  auto sink = [&](const char* data, std::size_t size) {
    written = written && (size == 0 || std::fwrite(data, 1, size, file) == size);
    return written;
  };
  bool ok = produce(sink) && written;
  ok = (std::fflush(file) == 0) && ok;
  ok = (std::ferror(file) == 0) && ok;
  ok = (std::fclose(file) == 0) && ok;
  if(ok)
  {
    fs::rename(temporary, destination, ec);
    ok = !ec;
  }
  if(!ok)
  {
    fs::remove(temporary, ec);
    return Error_code::CANNOT_OPEN_FILE;
  }
  return Error_code::SUCCESS;
}

// Writes `content` to `filename` all at once (see write_file_atomically_with()).
inline Error_code write_file_atomically(const std::string& filename, const std::string& content)
{
  return write_file_atomically_with(filename, [&](auto&& sink) { return sink(content.data(), content.size()); });
}

// Writes `content` to a user's stream in one go; CANNOT_OPEN_FILE if the
// stream is not writable or fails.
inline Error_code write_to_stream(std::ostream& os, const std::string& content)
{
  if(!os.good())
    return Error_code::CANNOT_OPEN_FILE;
  os.write(content.data(), static_cast<std::streamsize>(content.size()));
  os.flush();
  return os.good() ? Error_code::SUCCESS : Error_code::CANNOT_OPEN_FILE;
}

} // namespace internal
} // namespace IO
} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_IO_INTERNAL_ATOMIC_FILE_H
