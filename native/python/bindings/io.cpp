// hbc.load(): reads a mesh file into an hbc.Mesh.
#include "hbc/io.hpp"

#include <chrono>
#include <string>

#include "bindings.hpp"

namespace hbc::python {

namespace {

PyMeshPtr load(const py::object& path, const py::object& format, const py::object& threads, bool skip_invalid) {
  // os.fspath accepts str, bytes and path-likes (pathlib.Path) and raises TypeError for the rest.
  const std::string file = py::module_::import("os").attr("fspath")(path).cast<std::string>();
  const Format fmt = format.is_none() ? Format::Auto : format_from_name(format.cast<std::string>());
  Threads split;
  if (!threads.is_none()) {
    split.count = threads.cast<int>();
    if (split.count < 1) throw py::value_error("threads must be a positive number or None");
  }
  auto out = std::make_shared<PyMesh>();
  {
    py::gil_scoped_release unlocked;  // reading and building touch no Python objects
    const auto t0 = std::chrono::steady_clock::now();
    out->skip_invalid = skip_invalid;
    out->mesh = skip_invalid ? load_mesh_skipping_invalid(file, out->dropped, fmt, split) : load_mesh(file, fmt, split);
    out->load_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  }
  return out;
}

py::dict located(int64_t id, const SourceLoc& loc) {
  py::dict d;
  d["id"] = id;
  if (loc.line >= 0) d["line"] = loc.line;
  if (loc.byte_offset >= 0) d["byte"] = loc.byte_offset;
  return d;
}

// {"count", "by_reason", "cells"} of `hbc analyze --skip-invalid --json`'s "dropped".
py::dict dropped_cells_dict(const std::vector<DroppedCell>& dropped) {
  py::dict by;
  py::list cells;
  for (const DroppedCell& d : dropped) {
    const char* key = defect_key(d.reason);
    by[key] = (by.contains(key) ? by[key].cast<int64_t>() : 0) + 1;
    py::dict c = located(d.cell, d.loc);
    c["reason"] = key;
    cells.append(c);
  }
  py::dict out;
  out["count"] = dropped.size();
  out["by_reason"] = by;
  out["cells"] = cells;
  return out;
}

// The JSON of `hbc check --json` as a dict, key for key.
py::dict report_dict(const CheckReport& r) {
  py::dict defects;
  for (size_t k = 0; k < kDefectCount; ++k) {
    const auto d = static_cast<Defect>(k);
    py::list first;
    for (const DefectItem& it : r[d].first) {
      py::dict item = located(it.id, it.loc);
      if (d == Defect::Inverted || d == Defect::ZeroVolume) item["volume"] = it.volume;
      first.append(item);
    }
    py::dict cls;
    cls["count"] = r[d].count;
    cls["of"] = defect_subject(d);
    cls["refused"] = defect_refused(d);
    cls["dropped"] = r[d].dropped;
    cls["first"] = first;
    defects[defect_key(d)] = cls;
  }
  py::dict out;
  out["file"] = r.source;
  out["vertices"] = r.vertices;
  out["cells"] = r.cells;
  out["clean"] = r.clean();
  out["defects"] = defects;
  out["dropped"] = dropped_cells_dict(r.dropped);
  return out;
}

py::dict check(const py::object& path, const py::object& format, int first, const py::object& threads) {
  const std::string file = py::module_::import("os").attr("fspath")(path).cast<std::string>();
  const Format fmt = format.is_none() ? Format::Auto : format_from_name(format.cast<std::string>());
  if (first < 0) throw py::value_error("first must be 0 or more");
  Threads split;
  if (!threads.is_none()) split.count = threads.cast<int>();
  CheckReport r;
  {
    py::gil_scoped_release unlocked;
    r = check_file(file, fmt, static_cast<size_t>(first), split);
  }
  return report_dict(r);
}

}  // namespace

// The "dropped" member of `hbc analyze --skip-invalid --json` as a dict.
py::object dropped_dict(const PyMesh& p) {
  if (!p.skip_invalid) return py::none();
  return dropped_cells_dict(p.dropped);
}

void bind_io(py::module_& m) {
  m.def("load", &load, py::arg("path"), py::arg("format") = py::none(), py::kw_only(),
        py::arg("threads") = py::none(), py::arg("skip_invalid") = false,
        "Reads a volume mesh: a file, or an OpenFOAM case (its folder, .foam file or polyMesh/owner). "
        "format: a name of hbc.FORMATS ('ovm', 'mesh', 'foam', ...) or None to choose by the file extension. threads: how many threads read and build it (results are the same for "
        "any number); None: HBC_THREADS, else every core. Raises MeshFormatError (a ValueError) naming file and line on bad "
        "input, ValueError for an unknown format name. skip_invalid: drop the cells that cannot be volumes "
        "instead of raising (docs/check.md); Mesh.dropped then says which.");
  m.def("check", &check, py::arg("path"), py::arg("format") = py::none(), py::kw_only(), py::arg("first") = 10,
        py::arg("threads") = py::none(),
        "Every defect class of a file's cells (docs/check.md) as a dict with the keys of `hbc check --json`: "
        "file, vertices, cells, clean, defects {key: {count, of, refused, dropped, first: [{id, line|byte, volume}]}}, "
        "dropped (what skip_invalid=True drops: Mesh.dropped of that load). "
        "Raises MeshFormatError only for a file that cannot be read.");
}

}  // namespace hbc::python
