#pragma once
// Readers and writers for the volume mesh formats real hex-dominant meshers write.
// Every reader parses from memory (so fuzzers and tests need no files) and reports bad input as
// InputError with the file name and the line (byte offset for binary files).
#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "hbc/check.hpp"
#include "hbc/mesh.hpp"

namespace hbc {

enum class Format { Auto, Ovm, Ovmb, Medit, Hybrid, Hedra, Msh, Vtk, Vtu, Foam, Su2, Ugrid, Fluent, Exodus, Cgns, Abaqus, Nastran, LsDyna, Med, Xdmf };

// Every format hbc reads, in one list: the CLI's --format names and messages, the Python package's
// hbc.FORMATS and the Blender add-on's file filter come from it.
struct FormatInfo {
  Format format;
  std::string_view name;       // --format NAME and format_name(); also the extension, lower case
  std::string_view alias;      // another accepted name ("medit"), or empty
  std::string_view extension;  // as files usually spell it, with the dot (".HYBRID")
  std::string_view title;      // what writes it, in words
  bool writable;               // write_mesh writes it too
  std::string_view more_extensions = {};  // other extensions files of it carry (".nas"), space-separated
};
// Every extension of a format: its `extension`, then its `more_extensions`.
std::vector<std::string_view> extensions_of(const FormatInfo& f);
std::span<const FormatInfo> formats();

// A name or alias of formats() ("ovm", "mesh", "medit", ...); case-insensitive. Throws
// std::invalid_argument for anything else.
Format format_from_name(std::string_view name);
// By extension (case-insensitive): .ovm .ovmb .mesh .HYBRID .hedra .msh .vtk .vtu .foam .su2 .ugrid
// (also .b8.ugrid ...) .exo .e .g .cgns .inp .bdf .nas .k .key .med .xdmf .xmf; a folder
// and a polyMesh `owner` file (or owner.gz) are OpenFOAM too. Throws InputError otherwise.
Format format_from_path(const std::string& path);
const char* format_name(Format f);

// Format-specific readers. `source` names the file in messages.
MeshInput read_ovm(std::string_view text, const std::string& source);     // OpenVolumeMesh ASCII
MeshInput read_ovmb(std::string_view bytes, const std::string& source);   // OpenVolumeMesh binary
MeshInput read_medit(std::string_view text, const std::string& source,
                     const Threads& threads = {});                   // MEDIT .mesh
MeshInput read_hybrid(std::string_view text, const std::string& source);  // Robust Hex-Dominant .HYBRID
MeshInput read_hedra(std::string_view text, const std::string& source);   // LoopyCuts / cinolib .hedra
// Element-list formats: volume elements become cells (a hexahedron with repeated corners the
// polyhedron it stands for), points, lines and surface elements are skipped and counted in
// MeshInput::warnings. Binary files report byte offsets (.vtu always does).
MeshInput read_msh(std::string_view bytes, const std::string& source);    // Gmsh 2.2 / 4.1, ASCII or binary
MeshInput read_vtk(std::string_view bytes, const std::string& source);    // legacy VTK UNSTRUCTURED_GRID
MeshInput read_vtu(std::string_view bytes, const std::string& source);    // VTK XML UnstructuredGrid
MeshInput read_su2(std::string_view text, const std::string& source);     // SU2 native .su2 (zones joined)
// AFLR3 UGRID; the encoding is named by the file's second extension (ugrid_encoding_of):
// .ugrid ASCII, .b8.ugrid / .lb8.ugrid big- / little-endian binary, .r8.ugrid / .lr8.ugrid the same
// as Fortran unformatted records.
enum class UgridEncoding { Ascii, BigEndian, LittleEndian, FortranBigEndian, FortranLittleEndian };
UgridEncoding ugrid_encoding_of(const std::string& path);
MeshInput read_ugrid(std::string_view bytes, const std::string& source, UgridEncoding encoding);
// Fluent mesh .msh (ASCII and binary sections), face-based: cells from the faces' two sides.
// Gmsh's .msh starts with $MeshFormat, Fluent's with '(': read_input tells them apart by content.
MeshInput read_fluent(std::string_view bytes, const std::string& source);
// Exodus II through netCDF-C (classic, 64-bit offset or netCDF-4/HDF5, from memory): every element
// block, NFACED polyhedra over the face blocks; messages name the block and variable (no lines).
MeshInput read_exodus(std::string_view bytes, const std::string& source);
// CGNS through the CGNS library, which opens files only: this reader takes the path. Every zone of
// the first base, joined without merging shared vertices; structured zones as hexahedra.
MeshInput read_cgns(const std::string& path);
// Salome MED (MED-fichier 3.x/4.x) through HDF5's C library, from memory: the first mesh of
// /ENS_MAA at its first time step; volume elements by their corners (second-order ones too),
// converted from MED's corner order (or read as VTK's when the file was written so, as meshio
// writes it: decided per file, with a warning); messages name the HDF5 group or dataset (no lines).
MeshInput read_med(std::string_view bytes, const std::string& source);
// XDMF3 (.xdmf/.xmf): the first Grid's Topology and Geometry (XYZ), data inline or in HDF5 files
// named relative to `source`'s folder (read from disk). Lines for XML problems, the HDF5 dataset
// for data problems; without HDF5 only inline data is read.
MeshInput read_xdmf(std::string_view xml, const std::string& source);
// Builds without netCDF-C (HBC_EXODUS=OFF), the CGNS library (HBC_CGNS=OFF) or HDF5 (HBC_MED=OFF),
// and the WebAssembly core, list these formats and refuse their files with an InputError naming
// the missing library.

// Finite-element decks: nodes by label (any positive integers, in any order), volume elements by
// their corners (second-order ones too), beams, shells and points skipped and counted. A deck may
// include other files: `include` fetches one, given the including file's name and the path as
// written, and names it for messages (`name`); without it an include is an InputError. Cells and
// vertices from an included file are located at the line of the top file that includes it.
using IncludeReader = std::function<std::string(const std::string& from, const std::string& path, std::string& name)>;
// Included files from disk, relative to the including file's folder.
IncludeReader include_from_disk();
// Abaqus .inp: *NODE, *ELEMENT (C3D4/5/6/8/10/15/20/27 and their variants), parts flattened
// through their *INSTANCEs (translated and rotated, one label scope each), *INCLUDE.
MeshInput read_abaqus(std::string_view text, const std::string& source, const IncludeReader& include = {});
// Nastran bulk data .bdf/.nas: GRID, CHEXA, CPENTA, CPYRAM, CTETRA in small, large and free field;
// a GRID in a coordinate system other than the basic one is refused.
MeshInput read_nastran(std::string_view text, const std::string& source, const IncludeReader& include = {});
// LS-DYNA keyword .k/.key: *NODE, *ELEMENT_SOLID (fixed-width standard, long `+` and i10 `%`
// forms, free format; one- and two-card), hexahedra with repeated nodes as prisms, pyramids and tets.
MeshInput read_lsdyna(std::string_view text, const std::string& source, const IncludeReader& include = {});

// OpenFOAM constant/polyMesh: the bytes of its points, faces, owner and neighbour files (inflated
// when they were gzip-compressed) and the names messages give them. Each cell's faces are those it
// owns (seen as written) and those it neighbours (seen reversed), in face order; the MeshInput's
// source and face locations are those of the faces file.
struct FoamFiles {
  std::string_view points, faces, owner, neighbour;
  std::string points_name, faces_name, owner_name, neighbour_name;
};
MeshInput read_foam(const FoamFiles& files);
// The polyMesh folder of an OpenFOAM case given as its folder, a .foam marker file in it (as
// ParaView opens cases), constant/polyMesh itself or its owner file: the newest time folder's
// polyMesh when snappyHexMesh wrote one there, else constant/polyMesh. InputError naming `path`
// when it is none of these.
std::string foam_mesh_dir(const std::string& path);
// foam_mesh_dir + read_foam on its files, each plain or gzip-compressed (`points` or `points.gz`);
// or, for a decomposed case (foam_decomposed_case), read_foam_decomposed.
MeshInput read_foam_case(const std::string& path, const Threads& threads = {});

// Decomposed OpenFOAM cases (decomposePar's processor0/ .. processorN-1/). One processor: its
// polyMesh files and decomposePar's addressing beside them, labelLists giving for each local point,
// face and cell its id in the undecomposed mesh (faceProcAddressing: id + 1, negative where this
// processor sees the face reversed, i.e. the cell here is the face's neighbour); and its `boundary`
// file, whose processor patches name the processor holding each face's other side (empty: not
// checked).
struct FoamProcessorFiles {
  FoamFiles mesh;
  std::string_view point_addressing, face_addressing, cell_addressing;
  std::string point_addressing_name, face_addressing_name, cell_addressing_name;
  std::string_view boundary;
  std::string boundary_name;
};
// The processors' union as the undecomposed mesh, numbered as decomposePar's input was: the
// MeshInput read_foam gives for that mesh (points, face loops and cells equal, item for item;
// reconstructParMesh, which merges processors by geometry, numbers points and faces otherwise).
// Each processor-boundary face, seen by both sides, becomes one internal face. Processors are read
// in parallel; `source` names the case in messages. InputError naming the file and line (byte
// offset when binary) of a label out of range, of a processor patch whose faces lack their twins on
// the processor it names (or that processor's folder), and the case for counts that do not add up
// (a point, face or cell on no processor).
MeshInput join_foam_processors(std::span<const FoamProcessorFiles> processors, const std::string& source,
                               const Threads& threads = {});
// The case folder `path` asks to read decomposed, else empty: a path ending in `processor*` (the
// literal name: the case's processor folders joined, whatever else the case holds), or a case
// folder or .foam file whose case has processor0/ but no reconstructed mesh (no polyMesh `owner` in
// constant/ nor in a time folder).
std::string foam_decomposed_case(const std::string& path);
// join_foam_processors on the case's processor0/ .. processorN-1/, each processor's mesh where
// foam_mesh_dir finds it in the processor folder (constant/polyMesh or a time folder) with its
// addressing files beside it; a warning in the MeshInput says it was joined.
MeshInput read_foam_decomposed(const std::string& case_dir, const Threads& threads = {});

// Reads a whole file; throws InputError when it cannot be opened.
std::string read_file_bytes(const std::string& path);
MeshInput read_input(const std::string& path, Format format = Format::Auto, const Threads& threads = {});
// read_input + build_mesh.
Mesh load_mesh(const std::string& path, Format format = Format::Auto, const Threads& threads = {});
// read_input + build_mesh_skipping_invalid (hbc/check.hpp): the cells build_mesh would refuse
// are dropped and listed in `dropped` (--skip-invalid, skip_invalid=True).
Mesh load_mesh_skipping_invalid(const std::string& path, std::vector<DroppedCell>& dropped, Format format = Format::Auto,
                                const Threads& threads = {});
// read_input + check_input: InputError only for a file that cannot be read at all.
CheckReport check_file(const std::string& path, Format format = Format::Auto, size_t listed = 10, const Threads& threads = {});

// Writers. ovm_text keeps the mesh's numbering and each cell's view of its faces (read_ovm +
// build_mesh give back the same arrays). medit_text writes Hexahedra, Tetrahedra, Prisms and
// Pyramids sections in MEDIT's vertex order (cells grouped by type) and throws
// std::invalid_argument naming the cell for a general polyhedron, which MEDIT cannot express.
std::string ovm_text(const Mesh& mesh);
std::string medit_text(const Mesh& mesh);
void write_mesh(const Mesh& mesh, const std::string& path, Format format = Format::Auto);

}  // namespace hbc
