#pragma once
// GLSL 330 core sources from shaders/, embedded at build time (src/render/embed_shaders.cmake).
namespace kinema::shaders {
extern const char* const shaded_vert;
extern const char* const shaded_frag;
extern const char* const faceted_vert;
extern const char* const faceted_frag;
extern const char* const lines_vert;
extern const char* const lines_frag;
extern const char* const mesh_vert;
extern const char* const mesh_frag;
extern const char* const mesh_posed_vert;
extern const char* const sphere_impostor_vert;
extern const char* const sphere_impostor_frag;
extern const char* const overlay_vert;
extern const char* const overlay_frag;
}  // namespace kinema::shaders
