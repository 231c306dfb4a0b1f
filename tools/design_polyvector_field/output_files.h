// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

// design_polyvector_field: the output files (stage 2), checked before any
// work and written all or none, through the package's file transaction
// (IO/internal/atomic_file.h).

#ifndef PVF_TOOLS_DESIGN_POLYVECTOR_FIELD_OUTPUT_FILES_H
#define PVF_TOOLS_DESIGN_POLYVECTOR_FIELD_OUTPUT_FILES_H

#include "common.h"
#include "options.h"

#include <CGAL/Polyvector_fields/IO/internal/atomic_file.h>

#include <unistd.h>

#include <map>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

namespace pvf_cli {

class Output_files
{
public:
  // Checks every destination: a distinct file (not an input, not another
  // output, not a directory) in an existing, writable folder.
  Output_files(const Options& o)
  {
    std::map<std::string, std::string> claimed;  // canonical path -> what claims it
    for(const std::string* input : { &o.mesh, &o.constraints, &o.dmat_b, &o.dmat_bc })
      if(!input->empty())
        claimed[canonical(*input)] = "the input '" + *input + "'";
    const std::pair<const char*, const std::string*> outputs[] = {
      { "--out-field", &o.out_field }, { "--out-singularities", &o.out_singularities },
      { "--out-vtk", &o.out_vtk }, { "--out-mesh", &o.out_mesh }, { "--out-param", &o.out_param },
      { "--quad-mesh", &o.out_quads }, { "the quad-mesh VTK file of --quad-mesh and --out-vtk", &o.out_quads_vtk },
      { "--out-html", &o.out_html }, { "--out-ply", &o.out_ply } };
    for(const auto& output : outputs)
    {
      const std::string& path = *output.second;
      if(path.empty())
        continue;
      const std::string key = canonical(path);
      const auto previous = claimed.find(key);
      if(previous != claimed.end())
        throw Failure(std::string(output.first) + " '" + path + "' is the same file as " + previous->second, 2);
      claimed[key] = std::string(output.first) + " '" + path + "'";
      std::error_code ec;
      if(fs::is_directory(path, ec))
        throw Failure(std::string(output.first) + " '" + path + "' is a directory", 2);
      fs::path folder = fs::path(path).parent_path();
      if(folder.empty())
        folder = ".";
      if(!(o.default_outputs && folder == "output"))
      {
        if(!fs::exists(folder, ec))
          throw Failure(std::string(output.first) + " '" + path + "': the folder '" + folder.string() + "' does not exist", 2);
        if(!fs::is_directory(folder, ec))
          throw Failure(std::string(output.first) + " '" + path + "': '" + folder.string() + "' is not a folder", 2);
        if(::access(folder.c_str(), W_OK | X_OK) != 0)
          throw Failure(std::string(output.first) + " '" + path + "': the folder '" + folder.string() + "' is not writable", 2);
      }
      m_destinations.push_back(path);
    }
  }

  // Creates the default folder output/ if the outputs go there by default.
  void prepare(bool create_default_folder)
  {
    if(!create_default_folder)
      return;
    std::error_code ec;
    fs::create_directories("output", ec);
    if(ec)
      throw Failure("cannot create the folder output/: " + ec.message());
  }

  // Writes the content of `path` through `write` (which returns an
  // Error_code) into a fresh temporary file beside it, streamed: no copy of a
  // large output is kept in memory. publish() puts them all into place.
  // `detail`, if not empty once `write` failed, replaces the code's message.
  template <typename Write>
  void write(const std::string& path, const Write& write, const std::string& what,
             const std::string& detail = std::string())
  {
    const PVF::Error_code code = m_files.stage(path, write);
    if(code == PVF::Error_code::SUCCESS)
      return;
    if(!m_files.error_message().empty())
      throw Failure(m_files.error_message());
    check(code, "writing " + what, detail);
  }

  // Renames every temporary file over its destination. If any step fails,
  // the destinations are as they were before (replaced files are restored)
  // and no temporary remains.
  void publish()
  {
    for(const std::string& path : m_destinations)
      if(!m_files.is_staged(path))
        throw Failure("internal error: '" + path + "' was not written");
    if(m_files.commit() != PVF::Error_code::SUCCESS)
      throw Failure(m_files.error_message());
  }

  const std::vector<std::string>& destinations() const { return m_destinations; }

private:
  static std::string canonical(const std::string& path)
  {
    std::error_code ec;
    const fs::path p = fs::weakly_canonical(fs::absolute(path, ec), ec);
    return ec ? path : p.string();
  }

  std::vector<std::string> m_destinations;
  PVF::IO::internal::File_transaction m_files;
};

} // namespace pvf_cli

#endif // PVF_TOOLS_DESIGN_POLYVECTOR_FIELD_OUTPUT_FILES_H
