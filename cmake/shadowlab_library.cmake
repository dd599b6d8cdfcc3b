# shadowlab_library(NAME SOURCES file... HEADERS file-or-glob...): one library of the house,
# the target shadowlab_NAME with its alias shadowlab::NAME (the name it is exported under,
# cmake/install.cmake), and its headers as a file set based at the project root, so that a
# program includes "folder/x.h" in the tree and installed alike. HEADERS may be globs,
# relative to the calling folder, read again when a file is added.
function(shadowlab_library name)
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "" "SOURCES;HEADERS")
  add_library(shadowlab_${name} ${arg_SOURCES})
  add_library(shadowlab::${name} ALIAS shadowlab_${name})
  set_target_properties(shadowlab_${name} PROPERTIES EXPORT_NAME ${name})
  target_compile_features(shadowlab_${name} PUBLIC cxx_std_20)
  file(GLOB headers CONFIGURE_DEPENDS ${arg_HEADERS})
  target_sources(shadowlab_${name} PUBLIC FILE_SET HEADERS BASE_DIRS ${PROJECT_SOURCE_DIR} FILES ${headers})
endfunction()
