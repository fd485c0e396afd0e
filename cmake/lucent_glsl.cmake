# lucent_embed_glsl(<header-var> <output-dir>): the build rule for <output-dir>/lucent_glsl.h, holding
# every file of shaders/ and the generated optics constants (see embed_glsl.cmake). List the header
# among the sources of a target in the same directory to make it depend on the shaders. Shared by the
# top-level build and the ParaView plugin's build.
function(lucent_embed_glsl header_var output_dir)
  get_filename_component(root "${CMAKE_CURRENT_FUNCTION_LIST_DIR}/.." ABSOLUTE)
  file(GLOB glsl_files CONFIGURE_DEPENDS "${root}/shaders/*.glsl" "${root}/shaders/*.vert" "${root}/shaders/*.frag")
  list(SORT glsl_files)
  set(constants "${root}/include/lucent/optics/constants.hpp")
  set(header "${output_dir}/lucent_glsl.h")
  string(REPLACE ";" "\\;" glsl_arg "${glsl_files}")
  add_custom_command(OUTPUT "${header}"
    COMMAND ${CMAKE_COMMAND} -DCONSTANTS_HEADER=${constants} -DOUTPUT=${header} "-DGLSL_FILES=${glsl_arg}"
            -P "${root}/cmake/embed_glsl.cmake"
    DEPENDS ${glsl_files} "${constants}" "${root}/cmake/embed_glsl.cmake"
    COMMENT "Embedding shaders/ with the optics constants")
  set(${header_var} "${header}" PARENT_SCOPE)
endfunction()
