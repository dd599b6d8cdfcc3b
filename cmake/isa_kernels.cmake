# A vector kernel compiled once per instruction set (docs/architecture.md, "Vector kernels"):
# for each of scalar, AVX2 and AVX-512 a translation unit is generated from
# isa_kernel.cpp.in that includes the kernel's .inl files inside a namespace of its own, with
# `simd` bound to that set's types (raster/simd/), and defines FUNCTION<Isa>() returning the
# .inl's kernels(). Each unit is compiled alone with its set's flags, never in a unity batch
# (whose files share one set of flags).
#
#   shadowlab_isa_kernels(TARGET NAMESPACE shadowlab::izb STEM kernels FUNCTION kernels
#                         RETURNS Kernels HEADERS shadows/izb/kernels.h INLS shadows/izb/kernels.inl)
#
# defines shadowlab::izb::kernelsScalar(), kernelsAvx2() and kernelsAvx512(), as
# shadows/izb/kernels.h declares them.

# The flags of each instruction set, written once. GCC 12's own _mm512_undefined_*() (x = x)
# trips -Wuninitialized inside avx512fintrin.h; the same kernel source is warning-checked in
# the scalar and AVX2 units.
set(SHADOWLAB_ISA_FLAGS_scalar "")
set(SHADOWLAB_ISA_FLAGS_avx2 "-mavx2")
set(SHADOWLAB_ISA_FLAGS_avx512
    "-mavx512f;-mavx512bw;-mavx2;-Wno-uninitialized;$<$<CXX_COMPILER_ID:GNU>:-Wno-maybe-uninitialized>")

function(shadowlab_isa_kernels target)
  cmake_parse_arguments(K "" "NAMESPACE;STEM;FUNCTION;RETURNS" "HEADERS;INLS" ${ARGN})
  set(HEADER_INCLUDES "")
  foreach(header ${K_HEADERS})
    string(APPEND HEADER_INCLUDES "#include \"${header}\"\n")
  endforeach()
  set(INL_INCLUDES "")
  foreach(inl ${K_INLS})
    string(APPEND INL_INCLUDES "#include \"${inl}\"\n")
  endforeach()
  string(STRIP "${HEADER_INCLUDES}" HEADER_INCLUDES)
  string(STRIP "${INL_INCLUDES}" INL_INCLUDES)
  string(REPLACE ";" " and " INL_LIST "${K_INLS}")
  set(NAMESPACE ${K_NAMESPACE})
  set(STEM ${K_STEM})
  set(FUNCTION ${K_FUNCTION})
  set(RETURNS ${K_RETURNS})
  foreach(ISA scalar avx2 avx512)
    string(SUBSTRING ${ISA} 0 1 first)
    string(SUBSTRING ${ISA} 1 -1 rest)
    string(TOUPPER ${first} first)
    set(ISA_NAME ${first}${rest})
    set(unit ${CMAKE_CURRENT_BINARY_DIR}/isa/${K_STEM}_${ISA}.cpp)
    configure_file(${PROJECT_SOURCE_DIR}/cmake/isa_kernel.cpp.in ${unit} @ONLY)
    target_sources(${target} PRIVATE ${unit})
    set_source_files_properties(${unit} PROPERTIES SKIP_UNITY_BUILD_INCLUSION ON
                                COMPILE_OPTIONS "${SHADOWLAB_ISA_FLAGS_${ISA}}")
  endforeach()
endfunction()
