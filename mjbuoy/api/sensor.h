// sensors: MuJoCo user sensors that mjbuoy fills (docs/mjcf.md, section
// "Sensors"; docs/physics.md section 9)
#ifndef MJBUOY_SENSOR_H_
#define MJBUOY_SENSOR_H_

#include <string>
#include <vector>

#include <mujoco/mujoco.h>

namespace mjb {

struct Buoy;
struct State;

// quantities a sensor can be bound to
enum SensorKind {
  kSensElevation = 0,   // surface height eta at the site's x, y [m]
  kSensRelElevation,    // eta there minus the site's z [m]
  kSensVolume,          // body's submerged volume [m^3]
  kSensArea,            // body's wetted area [m^2]
  kSensWrench,          // body's mjbuoy wrench, total or one force family [N, N m]
  kSensTension,         // a line's tension at an end [N] (dim 1), or the end's force (dim 3)
  kSensBedLength,       // length of a line resting on the seabed [m]
};

struct Sensor {
  int id;      // MuJoCo sensor id
  int kind;    // SensorKind
  int obj;     // site id (elevations), body id, or line index (line quantities)
  int part;    // kSensWrench: force family (mjbPart), mjbNPART for the total;
               // kSensTension: the end, 0 anchor, 1 fairlead
  int h0, h1;  // hulls [h0, h1) of the body (they are contiguous)
};

// read the "mjbuoy.sensor.<sensor>" text entries of b's model into
// b->sensor; "" or the first error, which names the sensor
std::string parseSensors(Buoy* b);

// write every bound sensor whose needstage is stage into d->sensordata;
// s is d's state (NULL before the first passive call)
void fillSensors(const Buoy& b, const mjModel* m, mjData* d, const State* s, int stage);

}  // namespace mjb

#endif  // MJBUOY_SENSOR_H_
