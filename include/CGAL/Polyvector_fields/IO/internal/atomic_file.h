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
//
// `File_transaction` does the same for several files at once: each file is
// streamed into its own temporary, and commit() puts them all in place, or
// none of them (a program that writes a field, its singularities and a mesh
// leaves either all the new files or all the old ones).

#include <CGAL/Polyvector_fields/Error_code.h>

#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstddef>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <functional>
#include <map>
#include <ostream>
#include <random>
#include <streambuf>
#include <string>
#include <system_error>
#include <thread>
#include <utility>
#include <vector>

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

// Creates and opens for writing a fresh file beside `destination` (in the
// same directory, so that a rename into place does not cross file systems),
// named .<file name><tag><random suffix>; "x" refuses an existing file.
// Returns the file, with its path in `path`, or nullptr (errno says why).
inline std::FILE* open_temporary_beside(const std::filesystem::path& destination, const char* tag,
                                        std::filesystem::path& path)
{
  for(unsigned attempt = 0; attempt < 16; ++attempt)
  {
    path = destination;
    path.replace_filename("." + destination.filename().string() + tag + temporary_suffix(attempt));
    errno = 0;
    std::FILE* file = std::fopen(path.string().c_str(), "wbx");
    if(file != nullptr || errno != EEXIST)
      return file;
  }
  return nullptr;
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

  fs::path temporary;
  std::FILE* file = open_temporary_beside(destination, ".tmp-", temporary);
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

// An output stream buffer on a C file, with a large buffer of its own: the
// files of File_transaction are opened with "wbx" (refuse an existing file),
// which has no iostream equivalent. close() says whether every write worked.
class File_output_buffer : public std::streambuf
{
public:
  explicit File_output_buffer(std::FILE* file) : m_file(file), m_buffer(std::size_t(1) << 20)
  {
    setp(m_buffer.data(), m_buffer.data() + m_buffer.size());
  }
  File_output_buffer(const File_output_buffer&) = delete;
  File_output_buffer& operator=(const File_output_buffer&) = delete;
  ~File_output_buffer() override { close(); }

  // Writes what is buffered and closes the file; false if any write failed.
  bool close()
  {
    if(m_file == nullptr)
      return m_ok;
    drain();
    m_ok = (std::fflush(m_file) == 0) && m_ok;
    m_ok = (std::fclose(m_file) == 0) && m_ok;
    m_file = nullptr;
    return m_ok;
  }

protected:
  int_type overflow(int_type c) override
  {
    if(!drain())
      return traits_type::eof();
    if(!traits_type::eq_int_type(c, traits_type::eof()))
    {
      *pptr() = traits_type::to_char_type(c);
      pbump(1);
    }
    return traits_type::not_eof(c);
  }
  std::streamsize xsputn(const char* data, std::streamsize n) override
  {
    if(n < std::streamsize(m_buffer.size()))
      return std::streambuf::xsputn(data, n);
    // A large block (a whole formatted file): straight to the file.
    if(!drain() || std::fwrite(data, 1, std::size_t(n), m_file) != std::size_t(n))
      return m_ok = false, 0;
    return n;
  }
  int sync() override { return drain() ? 0 : -1; }

private:
  bool drain()
  {
    const std::size_t n = std::size_t(pptr() - pbase());
    if(m_file == nullptr || (n > 0 && std::fwrite(pbase(), 1, n, m_file) != n))
      m_ok = false;
    setp(m_buffer.data(), m_buffer.data() + m_buffer.size());
    return m_ok;
  }

  std::FILE* m_file;
  std::vector<char> m_buffer;
  bool m_ok = true;
};

// Several files written all or none.
//
//   File_transaction files;
//   if(files.stage("a.txt", [&](std::ostream& os) { ...; return Error_code::SUCCESS; }) != Error_code::SUCCESS
//      || files.commit() != Error_code::SUCCESS)
//     report(files.error_message());
//
// stage() streams one file into a fresh temporary beside its destination (no
// copy of a large file is kept in memory); commit() renames every temporary
// over its destination. If any step of commit() fails, every destination is
// as it was before (files it replaced are restored) and no temporary
// remains. A transaction destroyed before commit() removes its temporaries
// and leaves the destinations untouched.
class File_transaction
{
public:
  File_transaction() = default;
  File_transaction(const File_transaction&) = delete;
  File_transaction& operator=(const File_transaction&) = delete;
  ~File_transaction()
  {
    std::error_code ec;
    for(const auto& t : m_staged)
      std::filesystem::remove(t.second, ec);
  }

  // Writes the content of `destination` with `write(std::ostream&)`, which
  // returns an Error_code, into a temporary file. Returns SUCCESS; or the
  // code of `write` if it failed (error_message() is then empty: the writer
  // knows what went wrong); or CANNOT_OPEN_FILE if the temporary could not
  // be created or written (error_message() says why). Staging a destination
  // again replaces its content.
  template <typename Write>
  Error_code stage(const std::string& destination, Write&& write)
  {
    namespace fs = std::filesystem;
    m_error.clear();
    fs::path temporary;
    std::FILE* file = open_temporary_beside(fs::path(destination), ".tmp-", temporary);
    if(file == nullptr)
      return fail("cannot write '" + destination + "': " + std::strerror(errno));
    const auto previous = m_staged.find(destination);
    if(previous != m_staged.end())
    {
      std::error_code ec;
      fs::remove(previous->second, ec);
      previous->second = temporary.string();
    }
    else
    {
      m_order.push_back(destination);
      m_staged[destination] = temporary.string();
    }
    File_output_buffer buffer(file);
    std::ostream stream(&buffer);
    const Error_code code = write(stream);
    stream.flush();
    const bool written = buffer.close() && bool(stream);
    if(code != Error_code::SUCCESS)
      return code;
    if(!written)
      return fail("cannot write '" + destination + "': " + std::strerror(errno));
    return Error_code::SUCCESS;
  }

  // Whether `destination` has been staged and not yet committed.
  bool is_staged(const std::string& destination) const { return m_staged.count(destination) != 0; }

  // Puts every staged file in place, in the order they were first staged.
  // Existing destinations are moved aside first, so that they can be
  // restored. Returns SUCCESS, or CANNOT_OPEN_FILE (error_message() says
  // which file and why) with every destination as it was.
  Error_code commit()
  {
    namespace fs = std::filesystem;
    m_error.clear();
    std::vector<std::pair<std::string, std::string> > backups;  // destination, backup
    std::vector<std::string> placed;
    auto undo = [&]() {
      std::error_code ec;
      for(const std::string& path : placed)
        fs::remove(path, ec);
      for(const auto& b : backups)
        fs::rename(b.second, b.first, ec);
    };
    for(const std::string& path : m_order)
    {
      std::error_code ec;
      if(fs::exists(path, ec))
      {
        // A fresh name reserved by creating it; the rename replaces it.
        fs::path backup;
        std::FILE* reserved = open_temporary_beside(fs::path(path), ".old-", backup);
        if(reserved == nullptr)
        {
          undo();
          return fail("cannot replace '" + path + "': " + std::strerror(errno));
        }
        std::fclose(reserved);
        fs::rename(path, backup, ec);
        if(ec)
        {
          fs::remove(backup, ec);
          undo();
          return fail("cannot replace '" + path + "': " + ec.message());
        }
        backups.emplace_back(path, backup.string());
      }
      fs::rename(m_staged.at(path), path, ec);
      if(ec)
      {
        undo();
        return fail("cannot write '" + path + "': " + ec.message());
      }
      placed.push_back(path);
    }
    m_staged.clear();
    m_order.clear();
    std::error_code ec;
    for(const auto& b : backups)
      fs::remove(b.second, ec);
    return Error_code::SUCCESS;
  }

  // What failed last, as a sentence naming the file; empty after a success.
  const std::string& error_message() const { return m_error; }

private:
  Error_code fail(const std::string& message)
  {
    m_error = message;
    return Error_code::CANNOT_OPEN_FILE;
  }

  std::vector<std::string> m_order;                // destinations, in the order they were staged
  std::map<std::string, std::string> m_staged;     // destination -> its temporary file
  std::string m_error;
};

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
