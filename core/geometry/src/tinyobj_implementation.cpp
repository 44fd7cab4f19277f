// Debian's tinyobjloader is a single header; its implementation is compiled here, in double
// precision (TINYOBJLOADER_USE_DOUBLE, set for the whole target so mesh_io.cpp sees the same
// types), instead of linking the package's shared library. A program that links
// recode::geometry then needs no tinyobjloader library on its link line.
#define TINYOBJLOADER_IMPLEMENTATION
#include <tiny_obj_loader.h>
