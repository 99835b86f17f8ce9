# The layers, enforced by the build (docs/internals.md, "Layers"):
#
#   tioa-check (cli/main.cpp) > app (cli/) > catalogue > proofs > models, checker > tioa > support
#
# Every library sees, as its include path, only a folder of links to its own sources and
# those of the libraries it links: `tioa_include_root(checker checker)` gives checker the
# root build/include-roots/checker/ holding the one link checker -> <source>/checker, and
# the libraries checker links add theirs. A file that includes a layer above its own, or a
# layer beside it that its library does not link ("models/..." from checker/), therefore
# does not compile. Nothing has the source root itself on its include path.

# tioa_include_root(<target> <path>...): each <path> (relative to the source root, such as
# "checker" or "models/mc") becomes a link under the target's include root, so that
# #include "<path>/x.hpp" resolves. PUBLIC for libraries (their users see it too),
# PRIVATE for executables.
function(tioa_include_root target)
  set(root ${PROJECT_BINARY_DIR}/include-roots/${target})
  foreach(path ${ARGN})
    get_filename_component(parent ${root}/${path} DIRECTORY)
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
