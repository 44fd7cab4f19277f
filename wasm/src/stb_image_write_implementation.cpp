// stb_image_write's implementation for the module: the native program links Debian's libstb
// instead, so only this build compiles it.
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb/stb_image_write.h>
