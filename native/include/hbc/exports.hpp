#pragma once
// The binding surface, described once: every array the Python and the JavaScript bindings hand
// out (which object holds it, its name, dtype and shape, what it means) and every option of
// analyze (type, default, allowed values). The pybind11 module and the embind module register
// their arrays by name through this table (a name missing from it fails at module load), and the
// tests check the objects, `_core.pyi` and `hbc_core.d.ts` against it, so that the four surfaces
// cannot drift apart again. analyze_settings() is the one reader of analyze's options, for every
// CLI command that analyses and for Python's analyze(**kwargs) and JavaScript's analyze(options).
#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <variant>

#include "hbc/analysis.hpp"

namespace hbc {

enum class Dtype : uint8_t { Bool, UInt8, Int32, Float32, Float64 };
const char* dtype_name(Dtype d);  // numpy's name: "bool", "uint8", "int32", "float32", "float64"

// Which bindings hand an array out.
enum ExportSurface : uint8_t { kPython = 1, kJs = 2, kBoth = 3 };

// One exported array. Shapes are given libigl's way by a dimension (dimensions() says what each
// counts) and a width: (rows) when width is 0, (rows, width) otherwise; a CSR is two arrays,
// <name>_offsets, int32 (rows + 1), and <name>_items, int32 (<name>_offsets[rows]). JavaScript
// flattens (rows, width) into a typed array of width * rows, gives bool as Uint8Array 0/1, and
// holds the arrays of SingularityGraph and BaseComplex on Analysis itself (each embind property
// is a copy; one object per part would copy every array at once).
struct ExportedArray {
  std::string_view holder;  // the Python class or dict: Mesh, SingularityGraph, BaseComplex,
                            // Analysis, Subsheets, Wireframe, BlockSoup
  std::string_view name;    // the property (a CSR's stem)
  Dtype dtype;              // of the items for a CSR
  bool csr;
  std::string_view rows;    // a dimensions() symbol
  int width;                // 0: one value per row
  uint8_t surfaces;         // ExportSurface bits
  std::string_view deprecated;  // non-empty: a published name kept for old callers; what to use instead
  std::string_view meaning;
};
std::span<const ExportedArray> exported_arrays();
// The entry of `holder` named `name`: a plain array's name, a CSR's stem, or a CSR's
// <stem>_offsets / <stem>_items; nullptr when there is none.
const ExportedArray* find_exported_array(std::string_view holder, std::string_view name);

struct Dimension {
  std::string_view symbol;   // "nv", "ncomp", ...
  std::string_view meaning;  // what it counts, and where to read it
};
std::span<const Dimension> dimensions();

// "int32 (ne,)", "float32 (nv, 3)": numpy's dtype and shape of an entry's array (of the items
// for a CSR), as the Python docstrings and `_core.pyi` write it.
std::string numpy_shape_text(const ExportedArray& a);

// --- analyze's options -----------------------------------------------------------------------

enum class OptionType : uint8_t { Bool, Int, Real, Choice };
const char* option_type_name(OptionType t);  // "bool", "int", "float", "choice"

struct AnalyzeOption {
  std::string_view key;
  OptionType type;
  std::string_view default_text;  // as Python writes it: "0.8", "complex", "true", "none"
  std::string_view choices;       // Choice: the allowed names, separated by '|'
  double min, max;                // Int and Real: the allowed range (inclusive)
  std::string_view meaning;
};
std::span<const AnalyzeOption> analyze_options();
const AnalyzeOption* find_analyze_option(std::string_view key);

// A value as a front end has it: Python's and JSON's bool, int, float and str. An Int option
// takes an integral double too (JavaScript has numbers only); a Real one takes an int.
using OptionValue = std::variant<bool, int64_t, double, std::string>;
struct OptionSetting {
  std::string key;
  OptionValue value;
};

// What analyze takes: the analysis' options and the ρ its wireframes are styled at when no other
// is asked for (presentation, outside the analysis: render/wireframe_style).
struct AnalyzeSettings {
  AnalysisOptions options;
  double rho = 0.8;  // = WireframeStyleOptions{}.rho (a test keeps the two equal)
};

// An option key analyze does not take.
struct UnknownOptionError : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

// `defaults` with each setting applied in order. `level` sets the level of the sheets and of the
// wireframe; `subsheets` holds only with `sheets`. Throws UnknownOptionError for a key not in
// analyze_options() and std::invalid_argument naming the key, what it takes and what it got for a
// value of the wrong type or outside its range or choices.
AnalyzeSettings analyze_settings(std::span<const OptionSetting> settings, const AnalyzeSettings& defaults = {});

}  // namespace hbc
