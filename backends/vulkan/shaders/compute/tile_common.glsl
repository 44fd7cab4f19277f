// What every stage of the vulkan-compute device's tile rasterizer shares (docs/backends.md,
// "The compute device"): the frame's parameters, its records (defined once here; the host's
// mirror is tile_frame_layout.hpp, whose static_asserts keep the two in step), and the
// framebuffer's packing. Included after the stage's #version and extensions; needs
// GL_EXT_buffer_reference and GL_EXT_buffer_reference_uvec2.
//
// A frame is everything one submission runs: commands (draws, clears, reads) of every device,
// grouped by device and cut into epochs, runs of commands that depend on nothing before them
// (or, the first of a device's, on its framebuffer as the last frame left it). A job is one
// 8x8 block of one epoch's grid; the stages are: vertex (posed draws), set-up (every triangle
// of every draw), binning (count, scan, scatter, sort: each job's list of triangles in command
// order), raster (a job's commands on its 64 pixels, kept in registers), resolve (each pixel's
// final value from the last epoch that touched it).
//
// A framebuffer is one 32-bit word a pixel, rows from the bottom (GL window order): the
// contract's 24-bit depth q in the high bits and the 8-bit stencil in the low byte.

layout(push_constant) uniform Frame {
  uint vertexCount;    // posed vertices of the frame, over every vertex job
  uint vertexJobs;     // posed meshes whose window vertices the vertex stage makes
  uint triangleCount;  // set-up triangles of the frame, over every draw
  uint drawCount;
  uint jobCount;       // (epoch, 8x8 block) jobs
  uint epochCount;
  uint entryCapacity;  // entries the jobs' lists hold in all (Lists)
  uint resolvePixels;  // pixels the resolve stage visits, over every range
  uint resolveRanges;
  uint boxJobs;        // posed blocks whose world boxes the box stage makes
  uint binPass;        // tile_scatter.comp: 0 counts each job's triangles, 1 lists them
  // The work budgets that keep every invocation's loops within a CPU driver's limit
  // (tile_frame_budgets.hpp; kUnbounded on a GPU). A job that has spent its budget stops, keeps
  // where it is in the Progress words, and the next round of its stage carries on from there.
  uint rasterBudget;   // a raster job's work units a round (kWorkUnit a command or list entry)
  uint sortBudget;     // a sort job's loop iterations a round
  uint scatterBlocks;  // blocks one scatter invocation visits: a triangle's chunk of candidates
  uint scatterChunks;  // chunks of scatterBlocks each triangle's candidates are cut into
  uint round;          // the round of the stage being run, from 0
  uint roundGroupsX;   // the workgroups of a whole round of the stage being run
  uint roundGroupsY;
} frame;

// A budget that never runs out (a GPU driver's).
const uint kUnbounded = 0xFFFFFFFFu;
// The work a raster job is charged for each command (the loop's test and at most eight rows of
// a clear or read) and for each list entry or triangle it draws (the loop's test and at most
// eight rows): an invocation's loop iterations never exceed its work units.
const uint kWorkUnit = 9u;

// The frame's counters (Counters words, zero at the start of the frame): what each stage did,
// which the host compares with what it asked for (a loop a driver ended early shows here).
const uint kCounterRasterColumns = 0u;  // job columns the raster stage ran to their end
const uint kCounterSortedJobs = 1u;     // jobs whose lists the sort stage left in order
const uint kCounterScatterShort = 2u;   // scatter invocations whose loop ended early
const uint kCounterResolveShort = 3u;   // resolve invocations whose loop ended early

// Memory the records point at by address: a framebuffer, a draw's window vertices and indices, a
// posed mesh's object-space vertices.
layout(buffer_reference, std430, buffer_reference_align = 4) buffer PixelWords { uint pixels[]; };
layout(buffer_reference, std430, buffer_reference_align = 4) buffer FloatWords {
  float values[];
};
layout(buffer_reference, std430, buffer_reference_align = 4) buffer IndexWords { uint indices[]; };
layout(buffer_reference, std430, buffer_reference_align = 8) buffer DoubleWords {
  double values[];
};

// A device's framebuffer.
struct Target {
  uvec2 pixels;  // its address
  uint width;
  uint height;
};

// Command kinds.
const uint kDraw = 0u;
const uint kClearDepth = 1u;
const uint kClearStencil = 2u;
const uint kRead = 3u;

// Read forms: the depth q a word, the stencil a byte (four a word, packed by atomicOr into
// words the frame zeroed), the depth as the float q 2^-24 a word (what the summary shader
// and the other Vulkan device's copies hold; exact, since q < 2^24).
const uint kReadDepthWords = 0u;
const uint kReadStencilBytes = 1u;
const uint kReadDepthFloats = 2u;

struct Command {
  ivec4 rect;   // x0, y0, x1, y1 inside the target: a draw's or clear's scissor, a read's rectangle
  uint kind;
  uint target;
  uint tests;   // a draw's depth and stencil funcs, depth write, cull: see the decoders below
  uint stencil; // a draw's stencil reference and masks: likewise
  uint ops;     // a draw's stencil ops, both faces: likewise
  uint first;   // a draw's first triangle in the frame
  uint count;   // a draw's triangles
  uint value;   // a clear's value: q, or the stencil byte
  uint clearMask;  // a stencil clear's write mask
  uint readForm;   // a read's form (kRead...)
  uint arenaWord;  // a read's first word in the read arena
  uint pad;
};

// A draw's state, packed by the host in the three words above (tile_frame_layout.hpp's
// kTile...Shift constants: the same bits).
const uint kDepthWriteBit = 1u << 3;
const uint kStencilFuncShift = 4u;
const uint kCullShift = 7u;
const uint kValueMaskShift = 8u;
const uint kWriteMaskShift = 16u;
const uint kDepthFailShift = 3u;
const uint kDepthPassShift = 6u;
const uint kBackOpsShift = 9u;
uint depthFuncOf(Command c) { return c.tests & 7u; }
bool depthWriteOf(Command c) { return (c.tests & kDepthWriteBit) != 0u; }
uint stencilFuncOf(Command c) { return (c.tests >> kStencilFuncShift) & 7u; }
uint cullModeOf(Command c) { return (c.tests >> kCullShift) & 3u; }  // none, front, back
uint stencilRefOf(Command c) { return c.stencil & 0xFFu; }
uint valueMaskOf(Command c) { return (c.stencil >> kValueMaskShift) & 0xFFu; }
uint writeMaskOf(Command c) { return (c.stencil >> kWriteMaskShift) & 0xFFu; }
// A face's ops (nine bits: stencil fail, depth fail, depth pass) and one op of them.
uint faceOpsOf(Command c, bool front) {
  return front ? c.ops & 0x1FFu : (c.ops >> kBackOpsShift) & 0x1FFu;
}
uint stencilFailOp(uint faceOps) { return faceOps & 7u; }
uint depthFailOp(uint faceOps) { return (faceOps >> kDepthFailShift) & 7u; }
uint depthPassOp(uint faceOps) { return (faceOps >> kDepthPassShift) & 7u; }

// An epoch: the commands [firstCommand, commandEnd) of one target, drawn over a grid of 8x8
// blocks from gridOrigin, one job each from firstJob on.
const uint kEpochLoads = 1u;   // starts from the framebuffer (else from its own first clears)
const uint kEpochStores = 2u;  // no other epoch of the frame meets its footprint: stores directly
struct Epoch {
  ivec4 footprint;  // the pixels it may change, inside the target
  ivec2 gridOrigin; // the first block's lower-left pixel (multiples of 8)
  uint gridWidth;
  uint gridHeight;
  uint target;
  uint firstJob;
  uint firstCommand;
  uint commandEnd;
  uint flags;
  uint firstFinal;  // without kEpochStores: its jobs' slots in JobFinal, from this one on
  uint pad1;
  uint pad2;
};

// A draw's triangles: vertices (three floats each) and indices (three a triangle) by address.
struct DrawSource {
  uvec2 vertices;
  uvec2 indices;
  uint firstTriangle;
  uint triangleCount;
  uint command;
  uint epoch;
};

// A posed mesh to take to the window: object-space vertices (three doubles each) in, window
// vertices (three floats each) out, by the transform at transforms[23 transform].
struct VertexJob {
  uvec2 local;
  uvec2 windows;
  uint firstVertex;
  uint vertexCount;
  uint transform;
  uint pad;
};

// Pixels the resolve stage gives their final value: the footprint of one epoch that meets
// another, whose value a pixel takes unless one of the later epochs that meet it
// (laterEpochs[firstLater, + laterCount)) holds the pixel too; the range's pixels are numbered
// from firstPixel.
struct ResolveRange {
  ivec4 rect;
  uint target;
  uint epoch;
  uint firstLater;
  uint laterCount;
  uint firstPixel;
  uint pad0;
  uint pad1;
  uint pad2;
};

// A posed block whose world box the box stage makes: its object-space vertices, and its pose at
// poses[12 pose] (the linear part row by row, then the translation).
struct BoxJob {
  uvec2 local;
  uint vertexCount;
  uint pose;
};

// A set-up triangle (Triangles[]): what the set-up stage makes of a triangle for the binning and
// raster stages. Scalars and two-word vectors only, so that std430 lays it out as 16 words with
// no padding, as the host's TileSetUpTriangle (whose layout a test reads from these shaders'
// SPIR-V).
struct SetUpTriangle {
  int x0, y0, x1, y1, x2, y2;  // the snapped vertices (24.8 fixed point, |value| <= 2^23)
  uint front;                  // 1 front-facing, 0 back-facing
  int candidates[4];  // candidate pixels inside the scissor, half-open x0, y0, x1, y1 (empty:
                      // draws nothing; the only words a culled triangle's record is given)
  uint z0;            // z0's float bits
  uvec2 dzdx;         // the depth plane's slopes as double bits, low word first
  uvec2 dzdy;
};

// Sets `result` to the last index k below `count` whose array[k].field <= key, for records sorted
// by `field` with array[0].field <= key: the binary search that finds a frame index's record (a
// triangle's draw, a job's epoch, a vertex's job, a pixel's range). A macro, since GLSL has no
// function over any record type.
#define LAST_AT_OR_BELOW(result, array, field, count, key) \
  {                                                        \
    uint low_ = 0u;                                        \
    uint high_ = (count);                                  \
    while (high_ - low_ > 1u) {                            \
      const uint middle_ = (low_ + high_) / 2u;            \
      if (array[middle_].field <= (key))                   \
        low_ = middle_;                                    \
      else                                                 \
        high_ = middle_;                                   \
    }                                                      \
    result = low_;                                         \
  }

uint packPixel(uint q, uint s) {
  return (q << 8) | (s & 0xFFu);
}

uint depthOf(uint word) {
  return word >> 8;
}

uint stencilOf(uint word) {
  return word & 0xFFu;
}

// A vertex posed to world (raster/vertex_stage.hpp's poseVertex, docs/rasterization.md section
// 2.1): rows x and y ((l0 p0 + l1 p1) + l2 p2) + t, row z (l0 p0 + (l1 p1 + l2 p2)) + t, each
// operation `precise`, for a pose's linear part row by row (`x`, `y`, `z`) and its translation
// `t`. The vertex and box stages both pose by it, so a box holds the vertices the draws use.
dvec3 poseVertex(dvec3 x, dvec3 y, dvec3 z, dvec3 t, dvec3 p) {
  precise double wx = ((x[0] * p[0] + x[1] * p[1]) + x[2] * p[2]) + t[0];
  precise double wy = ((y[0] * p[0] + y[1] * p[1]) + y[2] * p[2]) + t[1];
  precise double wz = (z[0] * p[0] + (z[1] * p[1] + z[2] * p[2])) + t[2];
  return dvec3(wx, wy, wz);
}

// Pixel (row, column) of a job's 8x8 block in an array of 64 words a job (JobFinal, Carry).
uint pixelSlot(uint job, uint row, uint column) {
  return job * 64u + row * 8u + column;
}

bool insideRect(ivec4 r, int x, int y) {
  return x >= r.x && x < r.z && y >= r.y && y < r.w;
}

// The invocation's index in a one-dimensional dispatch of 64-wide workgroups that the host
// spread over rows of at most 65535 workgroups (the smallest limit a device may have).
uint linearInvocation() {
  return (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * 64u +
         gl_LocalInvocationID.x;
}

uint linearWorkgroup() {
  return gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x;
}
