// modelload: the one way every tool reads a user's model. The files a model
// reads are listed once (modelFiles): the output guard refuses to write over
// any of them (checkOutputs) and mjbuoy-sweep hashes them to tell a stale
// result. Loading checks the mesh files first (mjb_checkModelFile: MuJoCo
// 2.2 reads a bad face index out of bounds), then compiles with MuJoCo.
#ifndef MJBUOY_TOOLS_MODELLOAD_H_
#define MJBUOY_TOOLS_MODELLOAD_H_

#include <string>
#include <vector>

#include <mujoco/mujoco.h>

#include "outfile.h"

namespace mjbtool {

// the model file and every file it reads that exists: <include>s (nested),
// <mesh>, <hfield>, <skin> and <texture> files, resolved against the
// model's directory and its compiler meshdir, texturedir and assetdir
// (both candidates where MuJoCo versions differ). Sorted, no duplicates
std::vector<std::string> modelFiles(const std::string& xmlpath);

// uses plus the model and its files as inputs ("model", "mesh of the
// model", ...), then checkWritable for every output and checkDistinct
bool checkOutputs(const std::string& model, std::vector<PathUse> uses, std::string* err);

// the model's mesh files checked (mjb_checkModelFile), then the model
// compiled: from its file, or (xml not null) from that MJCF text as if it
// were a file in the model's directory (edited models; tag names it). Null
// with "cannot load MODEL: reason" in err
mjModel* loadModel(const std::string& path, const std::string* xml, const std::string& tag,
                   std::string* err);

}  // namespace mjbtool

#endif  // MJBUOY_TOOLS_MODELLOAD_H_
