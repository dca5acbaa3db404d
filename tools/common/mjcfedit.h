// mjbuoy.* <custom> entries of an MJCF document, edited with tinyxml2, and
// the edited model compiled from memory (shared by mjbuoy-scenario and
// mjbuoy-sim --set; docs/scenarios.md "Changing the model")
#ifndef MJBUOY_TOOLS_MJCFEDIT_H_
#define MJBUOY_TOOLS_MJCFEDIT_H_

#include <string>

#include <mujoco/mujoco.h>
#include <tinyxml2.h>

namespace mjbtool {

// the entry <numeric|text name="name"> in any <custom> of root, or null
tinyxml2::XMLElement* findEntry(tinyxml2::XMLElement* root, const std::string& name);

// set entry name to data as <text> (text) or <numeric>, replacing one of
// that name wherever it is; a new one goes into the first <custom> (made
// if the model has none)
void setEntry(tinyxml2::XMLDocument& doc, tinyxml2::XMLElement* root, const std::string& name,
              const std::string& data, bool text);

// delete entry name, or every entry whose name starts with it (prefix)
void removeEntries(tinyxml2::XMLElement* root, const std::string& name, bool prefix);

// delete every sea component: mjbuoy.wave.*, mjbuoy.airy.*, mjbuoy.spectrum.*
void removeSea(tinyxml2::XMLElement* root);

// compile the MJCF text xml as if it were a file in the directory of
// modelPath (so meshdir, mesh files and includes resolve as for the model)
// from a MuJoCo VFS; nothing is written to disk. tag names the in-memory
// file (".<tag>-<model file name>"). Null with MuJoCo's message in err
mjModel* loadFromMemory(const std::string& modelPath, const std::string& xml,
                        const std::string& tag, char* err, int errsz);

}  // namespace mjbtool

#endif  // MJBUOY_TOOLS_MJCFEDIT_H_
