#version 450
#extension GL_ARB_gpu_shader_int64 : require
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_buffer_reference : require
#extension GL_EXT_buffer_reference_uvec2 : require
// The frame's raster stage: every job (an 8x8 block of an epoch's grid) runs its epoch's
// commands in order on its 64 pixels, kept in registers from the first command to the last:
// clears, reads (into the read arena) and draws (the job's sorted list: the draw's triangles
// that may cover a centre of the block, in index order). Eight invocations take a job, one a
// column of its pixels; a workgroup of 64 takes eight jobs side by side (one a SIMD bundle of 8
// lanes on a CPU driver, two of 16, so a bundle's loop count is at most two jobs' own). Jobs of
// different epochs never share a pixel's state, so every job of the frame runs at once. Per
// triangle (its SetUpTriangle), an invocation works out its column's part once and steps down
// the rows the triangle's candidates reach, with the same operations in the same order as
// sections 5 and 7 of docs/rasterization.md:
//   coverage: each edge function E = dx (Yc - Ya) - dy (Xc - Xa) at the first row, then plus
//   256 dx a row (exact 64-bit integers), covered when E > 0 or E = 0 on an inclusive edge (4);
//   depth: z = (z0 + tx) + ty with tx = dzdx (Xc - X0) for the column and ty = dzdy (Yc - Y0)
//   for the row, each rounded on its own, then quantised (5);
//   then the stencil test, the depth test, the face's ops and the write masks (6).
// At the end a job that owns its pixels outright (kEpochStores) writes them to the
// framebuffer; any other keeps them in JobFinal for the resolve stage.
//
// Rounds: a job is charged kWorkUnit for each command and each triangle it draws; one that would
// pass Frame.rasterBudget (a CPU driver's loop limit, tile_frame_budgets.hpp) stops between two
// of them, keeps its pixels in Carry and its place in RasterProgress, and asks for the next round
// (its indirect dispatch in RasterRoundArgs), which carries on from there: the same operations in
// the same order, cut into pieces a driver runs in full. Every column that reaches its job's end
// with each loop left at its own test counts itself in Counters, which the host checks.

layout(local_size_x = 64) in;

#include "exact_contract.glsl"
#include "tile_common.glsl"
#include "tile_frame_inputs.glsl"
#include "tile_block_test.glsl"

// Read field by field. Against four uvec4 loads a record (the words named only in comments),
// on lavapipe with comb-translate-offset (12 alternating pairs of runs of 6 to 12 frames on a
// shared 2-core machine), the field reads' raster stage took 0.60 to 3.05 times as long, median
// 1.18: within the noise of one binary's own runs (up to 3x), so the named fields stay. On a
// GPU the wide loads are untimed (scripts/gpu-check.sh prints stage_ms_raster).
layout(std430, set = 0, binding = 6) readonly buffer Triangles { SetUpTriangle triangles[]; };
layout(std430, set = 0, binding = 7) readonly buffer BinEntries { uint binEntries[]; };
layout(std430, set = 0, binding = 8) readonly buffer BinOffsets { uint binOffsets[]; };
layout(std430, set = 0, binding = 10) readonly buffer Lists { uint lists[]; };
layout(std430, set = 0, binding = 11) writeonly buffer JobFinal { uint jobFinal[]; };
layout(std430, set = 0, binding = 12) buffer ReadArena { uint readArena[]; };
// Where a suspended job goes on: the round that goes on with it, the command it stopped at, its
// list cursor and, on a draw from every triangle, its next triangle. Two sets of jobCount
// records: round r reads set r % 2 (written in round r - 1) and writes the other, so no column
// reads its job's record while another column of it writes that record.
layout(std430, set = 0, binding = 17) buffer RasterProgress { uvec4 progress[]; };
layout(std430, set = 0, binding = 18) buffer Carry { uint carry[]; };  // 64 words a job
layout(std430, set = 0, binding = 19) buffer Counters { uint counters[]; };
// The rounds' indirect dispatches, three words a round (tile_rounds.glsl).
layout(std430, set = 0, binding = 20) buffer RasterRoundArgs { uint roundArgs[]; };

#include "tile_rounds.glsl"

// The state comes from each draw's command, so the compiler cannot take it as uniform: both
// functions are selects, not switches, which a CPU driver's SIMD code would run case by case.

// A comparison func (GL's numbering: bit 0 passes on less, bit 1 on equal, bit 2 on greater;
// NEVER 0 ... ALWAYS 7) of incoming against stored.
bool compare(uint func, uint incoming, uint stored) {
  const uint outcome = incoming < stored ? 0u : (incoming == stored ? 1u : 2u);
  return ((func >> outcome) & 1u) != 0u;
}

// A stencil op (KEEP 0, ZERO, REPLACE, INCR, INCR_WRAP, DECR, DECR_WRAP, INVERT 7) on s.
uint applyStencilOp(uint op, uint s, uint ref) {
  uint next = s;                                 // KEEP
  next = op == 1u ? 0u : next;                   // ZERO
  next = op == 2u ? ref : next;                  // REPLACE
  next = op == 3u ? min(s + 1u, 255u) : next;    // INCR
  next = op == 4u ? (s + 1u) & 0xFFu : next;     // INCR_WRAP
  next = op == 5u ? (s == 0u ? 0u : s - 1u) : next;  // DECR
  next = op == 6u ? (s + 255u) & 0xFFu : next;   // DECR_WRAP
  next = op == 7u ? 255u - s : next;             // INVERT
  return next;
}

// This invocation's column of the job being run: its x, its first row, and the eight pixels'
// depth and stencil.
int column;
int firstRow;
uint depth[8];
uint stencil[8];
// Whether a loop of this invocation ended other than at its own test (a driver's loop limit).
bool cut = false;
// The work units this invocation's job has spent this round.
uint spent = 0u;

// Charges the job one more unit of work (a command, or a triangle it draws) when its budget
// allows; false when the job must stop for the next round first.
bool affords() {
  if (spent + kWorkUnit > frame.rasterBudget)
    return false;
  spent += kWorkUnit;
  return true;
}

// The state of the draw being run, from its command.
uint ref;
uint valueMask;
uint writeMask;
uint frontOps;
uint backOps;
uint depthFunc;
uint stencilFunc;
bool depthWrite;

void takeState(Command c) {
  ref = stencilRefOf(c);
  valueMask = valueMaskOf(c);
  writeMask = writeMaskOf(c);
  frontOps = faceOpsOf(c, true);
  backOps = faceOpsOf(c, false);
  depthFunc = depthFuncOf(c);
  stencilFunc = stencilFuncOf(c);
  depthWrite = depthWriteOf(c);
}

// The edge a -> b of a counter-clockwise triangle at the centre (xc, yc): E minus the fill
// rule's bias (0 on an inclusive edge, 1 on another), so that a centre is covered when the
// value is >= 0; and its step from one row to the next.
int64_t biasedEdge(i64vec2 a, i64vec2 b, int64_t xc, int64_t yc) {
  const int64_t dx = b.x - a.x;
  const int64_t dy = b.y - a.y;
  return dx * (yc - a.y) - dy * (xc - a.x) - fillRuleBias(dx, dy);
}

// Frame triangle t's fragments in this column.
void shade(uint t) {
  // Its candidate rows in this block (the candidates lie inside the scissor).
  const int rowStart = max(triangles[t].candidates[1], firstRow);
  const int rowEnd = min(triangles[t].candidates[3], firstRow + 8);
  if (rowStart >= rowEnd || column < triangles[t].candidates[0] ||
      column >= triangles[t].candidates[2])
    return;
  const i64vec2 v0 = i64vec2(triangles[t].x0, triangles[t].y0);
  const i64vec2 v1 = i64vec2(triangles[t].x1, triangles[t].y1);
  const i64vec2 v2 = i64vec2(triangles[t].x2, triangles[t].y2);
  const bool front = triangles[t].front != 0u;
  // Counter-clockwise: (v0, v1, v2) when front-facing, (v0, v2, v1) when back-facing.
  const i64vec2 p1 = front ? v1 : v2;
  const i64vec2 p2 = front ? v2 : v1;
  const int64_t xc = int64_t(column) * 256l + 128l;
  const int64_t yc = int64_t(rowStart) * 256l + 128l;
  int64_t e0 = biasedEdge(v0, p1, xc, yc);
  int64_t e1 = biasedEdge(p1, p2, xc, yc);
  int64_t e2 = biasedEdge(p2, v0, xc, yc);
  const int64_t step0 = (p1.x - v0.x) * 256l;
  const int64_t step1 = (p2.x - p1.x) * 256l;
  const int64_t step2 = (v0.x - p2.x) * 256l;
  const double z0 = double(uintBitsToFloat(triangles[t].z0));
  const double dzdx = packDouble2x32(triangles[t].dzdx);
  const double dzdy = packDouble2x32(triangles[t].dzdy);
  precise double tx = dzdx * double(xc - v0.x);
  precise double zx = z0 + tx;  // the plane's column part, as CpuDevice keeps it per block
  const uint ops = front ? frontOps : backOps;
  int row = rowStart;
  for (; row < rowEnd; ++row) {
    if (e0 >= 0l && e1 >= 0l && e2 >= 0l) {
      const int k = row - firstRow;
      const uint s = stencil[k];
      uint op;
      if (!compare(stencilFunc, ref & valueMask, s & valueMask)) {
        op = stencilFailOp(ops);
      } else {
        precise double ty = dzdy * double(int64_t(row) * 256l + 128l - v0.y);
        precise double z = zx + ty;
        const uint q = quantizeDepth(z);
        if (!compare(depthFunc, q, depth[k])) {
          op = depthFailOp(ops);
        } else {
          op = depthPassOp(ops);
          if (depthWrite)
            depth[k] = q;
        }
      }
      const uint next = applyStencilOp(op, s, ref);
      stencil[k] = (next & writeMask) | (s & ~writeMask & 0xFFu);
    }
    e0 += step0;
    e1 += step1;
    e2 += step2;
  }
  cut = cut || row < rowEnd;
}

// A clear of this column's pixels inside the command's scissor.
void clear(Command c) {
  int k = 0;
  for (; k < 8; ++k) {
    if (!insideRect(c.rect, column, firstRow + k))
      continue;
    if (c.kind == kClearDepth) {
      depth[k] = c.value;
    } else {
      stencil[k] = (c.value & c.clearMask) | (stencil[k] & ~c.clearMask & 0xFFu);
    }
  }
  cut = cut || k < 8;
}

// A read of this column's pixels inside the command's rectangle, rows from the bottom, into the
// read arena from word c.arenaWord on.
void read(Command c) {
  const uint rectWidth = uint(c.rect.z - c.rect.x);
  int k = 0;
  for (; k < 8; ++k) {
    const int row = firstRow + k;
    if (!insideRect(c.rect, column, row))
      continue;
    const uint at = uint(row - c.rect.y) * rectWidth + uint(column - c.rect.x);
    if (c.readForm == kReadStencilBytes)
      atomicOr(readArena[c.arenaWord + at / 4u], stencil[k] << (8u * (at % 4u)));
    else if (c.readForm == kReadDepthWords)
      readArena[c.arenaWord + at] = depth[k];
    else
      readArena[c.arenaWord + at] = floatBitsToUint(float(depth[k]) * (1.0 / 16777216.0));
  }
  cut = cut || k < 8;
}

// This column's pixel words of job j: loaded at its first round, or carried from the last.
void loadPixels(uint j, Epoch epoch, Target target, PixelWords framebuffer, bool resumed) {
  const uint lane = gl_LocalInvocationID.x & 7u;
  const bool loads = (epoch.flags & kEpochLoads) != 0u;
  int k = 0;
  for (; k < 8; ++k) {
    const int row = firstRow + k;
    // An epoch that starts from its own clears reads nothing: its pixels outside them are
    // never touched (every command of such an epoch lies inside the clears' rectangle).
    const bool inside = loads && column < int(target.width) && row < int(target.height);
    uint word;
    if (resumed)  // Carry holds a record a job only where a job may be resumed
      word = carry[pixelSlot(j, uint(k), lane)];
    else
      word = inside ? framebuffer.pixels[uint(row) * target.width + uint(column)]
                    : packPixel(0xFFFFFFu, 0u);
    depth[k] = depthOf(word);
    stencil[k] = stencilOf(word);
  }
  cut = cut || k < 8;
}

// Stops job j where it is (command ci, list cursor, next triangle t of a draw from every
// triangle) for the next round: this column's pixels to Carry, the place to RasterProgress (the
// same in every column), and the next round's dispatch asked for.
void suspend(uint j, uint ci, uint cursor, uint t) {
  const uint lane = gl_LocalInvocationID.x & 7u;
  int k = 0;
  for (; k < 8; ++k)
    carry[pixelSlot(j, uint(k), lane)] = packPixel(depth[k], stencil[k]);
  cut = cut || k < 8;
  if (lane == 0u) {
    const uint written = ((frame.round + 1u) & 1u) * frame.jobCount + j;
    progress[written] = uvec4(frame.round + 1u, ci, cursor, t);
    askNextRound();
  }
}

// This column's pixels at the end of job j: to the framebuffer when the job owns them, else to
// JobFinal for the resolve stage.
void storePixels(uint j, Epoch epoch, Target target, PixelWords framebuffer) {
  const uint block = j - epoch.firstJob;
  const bool stores = (epoch.flags & kEpochStores) != 0u;
  int k = 0;
  for (; k < 8; ++k) {
    const uint word = packPixel(depth[k], stencil[k]);
    if (stores) {
      if (insideRect(epoch.footprint, column, firstRow + k))
        framebuffer.pixels[uint(firstRow + k) * target.width + uint(column)] = word;
    } else {
      jobFinal[pixelSlot(epoch.firstFinal + block, uint(k), gl_LocalInvocationID.x & 7u)] = word;
    }
  }
  cut = cut || k < 8;
}

// Runs job j, this invocation's column of it, from where an earlier round left it, until its
// end or its budget.
void runJob(uint j) {
  // RasterProgress is read only from the second round on: in the first (the only one where the
  // budget is unbounded) its buffer may hold no record a job.
  const bool resumed = frame.round > 0u;
  uvec4 place = uvec4(0u);
  if (resumed) {
    place = progress[(frame.round & 1u) * frame.jobCount + j];
    if (place.x != frame.round)
      return;  // done in an earlier round
  }
  const uint e = epochOfJob(j);
  const Epoch epoch = epochs[e];
  const Target target = targets[epoch.target];
  PixelWords framebuffer = PixelWords(target.pixels);
  const uint block = j - epoch.firstJob;
  column = epoch.gridOrigin.x + int((block % epoch.gridWidth) * 8u + (gl_LocalInvocationID.x & 7u));
  firstRow = epoch.gridOrigin.y + int((block / epoch.gridWidth) * 8u);
  loadPixels(j, epoch, target, framebuffer, resumed);
  uint cursor = resumed ? place.z : binOffsets[j];
  const uint listEnd = binOffsets[j] + binEntries[j];
  const bool overflowed = listEnd > frame.entryCapacity;
  uint ci = resumed ? place.y : epoch.firstCommand;
  bool midCommand = resumed;  // the first command was begun (and charged) in an earlier round
  for (; ci < epoch.commandEnd; ++ci) {
    const Command c = commands[ci];
    if (!midCommand && !affords()) {
      suspend(j, ci, cursor, c.first);
      return;
    }
    if (c.kind == kDraw) {
      takeState(c);
      const uint drawEnd = c.first + c.count;
      if (overflowed) {
        // The list did not fit: every triangle of the draw, in index order (a set-up triangle
        // that misses this column is skipped by its candidate rectangle).
        uint t = midCommand ? place.w : c.first;
        for (; t < drawEnd; ++t) {
          if (!affords()) {
            suspend(j, ci, cursor, t);
            return;
          }
          shade(t);
        }
        cut = cut || t < drawEnd;
      } else {
        // The list is in frame order, which is command order: this draw's entries are next.
        for (; cursor < listEnd && lists[cursor] < drawEnd; ++cursor) {
          if (!affords()) {
            suspend(j, ci, cursor, 0u);
            return;
          }
          shade(lists[cursor]);
        }
        cut = cut || (cursor < listEnd && lists[cursor] < drawEnd);
      }
    } else if (c.kind == kRead) {
      read(c);
    } else {
      clear(c);
    }
    midCommand = false;
  }
  cut = cut || ci < epoch.commandEnd;
  storePixels(j, epoch, target, framebuffer);
  if (!cut)
    atomicAdd(counters[kCounterRasterColumns], 1u);
}

// Invocation i runs column i % 8 of the workgroup's job i / 8: eight jobs side by side.
void main() {
  const uint j = linearWorkgroup() * 8u + (gl_LocalInvocationID.x >> 3);
  if (j < frame.jobCount)
    runJob(j);
}
