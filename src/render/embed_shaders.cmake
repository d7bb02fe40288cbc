# Writes OUTPUT (a .cpp) holding every file in SHADERS as a string constant, so the
# installed binary never reads the source tree. Run with cmake -P at build time.
set(code "// Generated from shaders/ by src/render/embed_shaders.cmake; do not edit.\n#include \"render/shader_sources.h\"\n\nnamespace kinema::shaders {\n")
foreach(path ${SHADERS})
  get_filename_component(name ${path} NAME)
  string(MAKE_C_IDENTIFIER ${name} id)
  file(READ ${path} text)
  string(APPEND code "const char* const ${id} = R\"kinema_glsl(${text})kinema_glsl\";\n")
endforeach()
string(APPEND code "}  // namespace kinema::shaders\n")
file(WRITE ${OUTPUT}.tmp "${code}")
file(COPY_FILE ${OUTPUT}.tmp ${OUTPUT} ONLY_IF_DIFFERENT)
