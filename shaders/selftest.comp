#version 430
// self test of the GL plumbing (tests/gl_test.cc), two stages:
// stage 0: y = a x + b for every item, one invocation per item
// stage 1: one workgroup per segment sums y over its items in a fixed order
//          (strided partial sums, then a tree in shared memory), so the
//          result does not depend on scheduling and segments may have any
//          length; the per-body wrench sums will work the same way
#include "shared.h"

layout(local_size_x = SELFTEST_LOCAL) in;

layout(std430, binding = SELFTEST_ITEMS) buffer Items {
  SelftestItem item[];
};

layout(std430, binding = SELFTEST_SEGMENTS) buffer Segments {
  SelftestSegment seg[];
};

uniform int stage;   // 0 or 1
uniform int nitem;   // items in Items

shared float part[SELFTEST_LOCAL];

void main() {
  uint lid = gl_LocalInvocationID.x;
  if (stage == 0) {
    uint i = gl_GlobalInvocationID.x;
    if (i < uint(nitem)) item[i].y = item[i].a * item[i].x + item[i].b;
    return;
  }

  // stage 1: workgroup s reduces segment s
  SelftestSegment sg = seg[gl_WorkGroupID.x];
  float s = 0.0;
  for (int i = int(lid); i < sg.count; i += SELFTEST_LOCAL) s += item[sg.start + i].y;
  part[lid] = s;
  barrier();
  for (uint h = SELFTEST_LOCAL / 2; h > 0; h /= 2) {
    if (lid < h) part[lid] += part[lid + h];
    barrier();
  }
  if (lid == 0) seg[gl_WorkGroupID.x].sum = part[0];
}
