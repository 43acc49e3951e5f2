# Assembles the add-on folder (cmake -P): the add-on's sources with their subpackages, the hbc
# package with every compiled module built so far (the build's own and those of the wheels of other
# Pythons), and the project's one version written into bl_info and the manifest.
#   -DSRC=<addon sources> -DPKG=<hbc package sources> -DCORE=<_core file> -DEXTRA=<folder of
#   extra _core modules> -DOUT=<add-on folder> -DVERSION=x.y.z
file(REMOVE_RECURSE ${OUT})
file(MAKE_DIRECTORY ${OUT}/hbc)
file(GLOB_RECURSE sources RELATIVE ${SRC} ${SRC}/*.py ${SRC}/*.toml ${SRC}/*.md)
foreach(name ${sources})
  file(READ ${SRC}/${name} text)
  if(name STREQUAL "__init__.py")  # the package's own, not a subpackage's
    string(REPLACE "." ", " tuple ${VERSION})
    string(REGEX REPLACE "\"version\": \\([0-9, ]+\\)" "\"version\": (${tuple})" text "${text}")
  elseif(name STREQUAL "blender_manifest.toml")
    string(REGEX REPLACE "\nversion = \"[0-9.]+\"" "\nversion = \"${VERSION}\"" text "${text}")
  endif()
  file(WRITE ${OUT}/${name} "${text}")
endforeach()
file(GLOB pkg ${PKG}/*)
file(COPY ${pkg} ${CORE} DESTINATION ${OUT}/hbc)
file(GLOB extra ${EXTRA}/_core.*)
if(extra)
  file(COPY ${extra} DESTINATION ${OUT}/hbc)
endif()
