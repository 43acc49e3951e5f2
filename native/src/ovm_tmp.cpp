// TEMPORARY (replaced by the OVM work in this session)
#include "hbc/io.hpp"
namespace hbc {
MeshInput read_ovm(std::string_view, const std::string& s) { throw InputError(s, {}, "ovm reader not built yet"); }
MeshInput read_ovmb(std::string_view, const std::string& s) { throw InputError(s, {}, "ovmb reader not built yet"); }
std::string ovm_text(const Mesh&) { return {}; }
std::string medit_text(const Mesh&) { return {}; }
}
