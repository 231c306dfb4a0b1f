// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

// Helpers shared by the IO tests: bundled data, whole-file reads, scratch folders.

#ifndef CGAL_POLYVECTOR_FIELDS_IO_TEST_SUPPORT_H
#define CGAL_POLYVECTOR_FIELDS_IO_TEST_SUPPORT_H

#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>

#ifndef PVF_DATA_DIR
#error "PVF_DATA_DIR (the folder of the bundled meshes) must be given by the build (CMake's pvf_link_package)"
#endif

namespace pvf_io_test {

inline std::string data_file(const std::string& name) { return std::string(PVF_DATA_DIR) + "/" + name; }

template <typename TriangleMesh>
TriangleMesh load_mesh(const std::string& name)
{
  TriangleMesh tm;
  const bool ok = CGAL::IO::read_polygon_mesh(data_file(name), tm);
  if(!ok || num_faces(tm) == 0)
    throw std::runtime_error("cannot read " + name);
  return tm;
}

inline std::string file_content(const std::string& filename)
{
  std::ifstream in(filename, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

class Scratch_directory
{
public:
  explicit Scratch_directory(const std::string& name)
  {
    m_path = std::filesystem::temp_directory_path() / ("pvf_io_test_" + name + "_" + std::to_string(std::random_device()()));
    std::filesystem::remove_all(m_path);
    std::filesystem::create_directories(m_path);
  }
  ~Scratch_directory() { std::error_code ec; std::filesystem::remove_all(m_path, ec); }
  std::string file(const std::string& name) const { return (m_path / name).string(); }
  std::set<std::string> entries() const
  {
    std::set<std::string> names;
    for(const auto& entry : std::filesystem::directory_iterator(m_path))
      names.insert(entry.path().filename().string());
    return names;
  }

private:
  std::filesystem::path m_path;
};

} // namespace pvf_io_test

#endif // CGAL_POLYVECTOR_FIELDS_IO_TEST_SUPPORT_H
