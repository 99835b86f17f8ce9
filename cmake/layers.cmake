# The layers, enforced by the build (docs/internals.md, "Layers"):
#
#   tioa-check (cli/main.cpp, round, simulate) > app (cli/), builtin (catalogue/<model>)
#   app > catalogue (catalogue/registry, param_value) > checker
#   builtin > catalogue, proofs > models, checker > tioa > support
#
# app (the command line as a library, cli::run) and catalogue (ModelDefinition, Catalogue)
# see neither proofs/ nor models/: a program of its own links them (tioa::app) without the
# built-in models.
#
# Every library sees, as its include path, only a folder of links to its own sources and
# those of the libraries it links: `tioa_include_root(checker checker)` gives checker the
# root build/include-roots/checker/ holding the one link checker -> <source>/checker, and
# the libraries checker links add theirs. A file that includes a layer above its own, or a
# layer beside it that its library does not link ("models/..." from checker/), therefore
# does not compile. Nothing has the source root itself on its include path.

# tioa_include_root(<target> <path>...): each <path> (relative to the source root, such as
# "checker" or "models/mc") becomes a link under the target's include root, so that
# #include "<path>/x.hpp" resolves. A <path> may also be one file ("cli/app.hpp"), where a
# folder holds the files of two libraries. PUBLIC for libraries (their users see it too),
# PRIVATE for executables.
function(tioa_include_root target)
  set(root ${PROJECT_BINARY_DIR}/include-roots/${target})
  foreach(path ${ARGN})
    get_filename_component(parent ${root}/${path} DIRECTORY)
    # A folder an older configuration linked whole, where files are linked now: remove the
    # link (not the folder it points to), or the files would be linked onto themselves.
    if(IS_SYMLINK ${parent})
      file(REMOVE ${parent})
    endif()
    file(MAKE_DIRECTORY ${parent})
    if(NOT IS_SYMLINK ${root}/${path})
      file(CREATE_LINK ${PROJECT_SOURCE_DIR}/${path} ${root}/${path} SYMBOLIC)
    endif()
  endforeach()
  get_target_property(type ${target} TYPE)
  if(type STREQUAL "EXECUTABLE")
    target_include_directories(${target} PRIVATE ${root})
  elseif(type STREQUAL "INTERFACE_LIBRARY")
    target_include_directories(${target} INTERFACE $<BUILD_INTERFACE:${root}>)
  else()
    target_include_directories(${target} PUBLIC $<BUILD_INTERFACE:${root}>)
  endif()
endfunction()
