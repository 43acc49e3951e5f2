# The WebAssembly build (emscripten; scripts/build_wasm.sh, docs/wasm.md). Included by the top-level
# CMakeLists.txt before native/ when EMSCRIPTEN is set. Emscripten's toolchain finds nothing
# outside its sysroot, and its "ports" download at build time, so what the native build takes from
# Debian is made here: zlib and pugixml from Debian's source packages (HBC_WASM_DEPS_DIR, fetched
# by the script), GoogleTest from /usr/src/googletest, and the header-only libraries (Boost.Graph,
# CLI11, nlohmann-json, fast_float) through a folder of links to exactly those headers, so that no
# other host header can shadow the sysroot's.
enable_language(C)
set(HBC_WASM_DEPS_DIR "${CMAKE_BINARY_DIR}/deps" CACHE PATH "Folder holding zlib/ and pugixml/ (Debian's sources)")
set(HBC_WASM_ZLIB_DIR "${HBC_WASM_DEPS_DIR}/zlib")
set(HBC_WASM_PUGIXML_DIR "${HBC_WASM_DEPS_DIR}/pugixml")
foreach(d ${HBC_WASM_ZLIB_DIR}/zlib.h ${HBC_WASM_PUGIXML_DIR}/src/pugixml.hpp)
  if(NOT EXISTS ${d})
    message(FATAL_ERROR "${d} is missing: run scripts/build_wasm.sh, which fetches Debian's zlib and pugixml sources")
  endif()
endforeach()

# The readers throw (InputError): exceptions on in every object and at every link. The heap grows
# up to 4 GB (a 10^6-cell mesh takes about 1 GB while it loads).
add_compile_options(-fexceptions "$<$<COMPILE_LANGUAGE:CXX>:SHELL:-include ${CMAKE_CURRENT_LIST_DIR}/libcxx_compat.hpp>")
add_link_options(-fexceptions -sALLOW_MEMORY_GROWTH=1 -sMAXIMUM_MEMORY=4GB)

set(HBC_WASM_HOST_HEADERS ${CMAKE_BINARY_DIR}/host-headers)
file(MAKE_DIRECTORY ${HBC_WASM_HOST_HEADERS})
foreach(h boost CLI nlohmann fast_float)
  if(NOT EXISTS ${HBC_WASM_HOST_HEADERS}/${h})
    file(CREATE_LINK /usr/include/${h} ${HBC_WASM_HOST_HEADERS}/${h} SYMBOLIC)
  endif()
endforeach()
include_directories(SYSTEM ${HBC_WASM_HOST_HEADERS})

set(zsrc adler32.c compress.c crc32.c deflate.c gzclose.c gzlib.c gzread.c gzwrite.c infback.c inffast.c
    inflate.c inftrees.c trees.c uncompr.c zutil.c)
list(TRANSFORM zsrc PREPEND ${HBC_WASM_ZLIB_DIR}/)
add_library(hbc_wasm_zlib STATIC ${zsrc})
target_compile_definitions(hbc_wasm_zlib PRIVATE HAVE_UNISTD_H)
target_include_directories(hbc_wasm_zlib SYSTEM PUBLIC ${HBC_WASM_ZLIB_DIR})
add_library(ZLIB::ZLIB ALIAS hbc_wasm_zlib)

add_library(hbc_wasm_pugixml STATIC ${HBC_WASM_PUGIXML_DIR}/src/pugixml.cpp)
target_include_directories(hbc_wasm_pugixml SYSTEM PUBLIC ${HBC_WASM_PUGIXML_DIR}/src)
add_library(pugixml::static ALIAS hbc_wasm_pugixml)

add_library(hbc_wasm_header_only INTERFACE)
add_library(CLI11::CLI11 ALIAS hbc_wasm_header_only)
add_library(nlohmann_json::nlohmann_json ALIAS hbc_wasm_header_only)

if(HBC_BUILD_TESTS)
  set(gt /usr/src/googletest/googletest)
  add_library(hbc_wasm_gtest STATIC ${gt}/src/gtest-all.cc)
  target_include_directories(hbc_wasm_gtest SYSTEM PUBLIC ${gt}/include PRIVATE ${gt})
  add_library(hbc_wasm_gtest_main STATIC ${gt}/src/gtest_main.cc)
  target_link_libraries(hbc_wasm_gtest_main PUBLIC hbc_wasm_gtest)
  add_library(GTest::gtest ALIAS hbc_wasm_gtest)
  add_library(GTest::gtest_main ALIAS hbc_wasm_gtest_main)
endif()
