// roofline: mjbuoy-bench's reference of what the machine allows, a vector
// kernel of the cpu backend's arithmetic per triangle timed on this core
#ifndef MJBUOY_TOOLS_ROOFLINE_H_
#define MJBUOY_TOOLS_ROOFLINE_H_

namespace mjbtool {

// CPU ns per triangle of the reference kernel (roofline.cc) on a sea of nw
// components, one thread, best of several passes over a 7744-triangle
// mesh's worth of structure-of-arrays data
double rooflineNs(int nw);

}  // namespace mjbtool

#endif  // MJBUOY_TOOLS_ROOFLINE_H_
