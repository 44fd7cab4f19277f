#version 450
// The native Vulkan device's only shader (docs/backends.md): GL window coordinates, snapped to
// the 24.8 grid on the host, to clip space through the device's viewport, as the fixed-function
// GL device's projection does. The viewport is P x Q pixels, powers of two, centred on the
// framebuffer: x_clip = (x - cx) 2/P is exact in float (x - cx has at most 24 significant bits
// and 2/P is a power of two), and the driver's viewport transform gives x back unchanged.
// Depth passes through (clip z = window z, w = 1). No fragment stage: coverage, the depth
// interpolation and its conversion to the attachment's format are the driver's own.

layout(location = 0) in vec3 position;  // x, y in GL window coordinates; z in [0, 1]

layout(push_constant) uniform Window {
  vec2 centre;  // the viewport's centre (cx, cy) in GL window coordinates
  vec2 scale;   // 2/P, 2/Q
} window;

void main() {
  precise vec2 ndc = (position.xy - window.centre) * window.scale;
  gl_Position = vec4(ndc, position.z, 1.0);
}
