#pragma once
// A camera path for offline renders (docs/camera-path.md): keyframes with a time, a position, an
// orientation (a target to look at, or a quaternion), a world scale and graph parameters, eased
// between keys.
// Sampling is a pure function of the frame number, so any frame rendered alone is the same frame
// as in a full run.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "common/diagnostics.h"
#include "frame/stereo_rig.h"

namespace fg {

enum class Ease { Linear, In, Out, InOut };

struct CameraKey {
    double time = 0.0;                          // seconds
    glm::dvec3 position{0.0};
    std::optional<glm::dvec3> target;           // look at this point ...
    glm::dvec3 up{0.0, 1.0, 0.0};
    glm::dquat orientation{1.0, 0.0, 0.0, 0.0}; // ... or turn this way (-z forward, +y up)
    double world_scale = 1.0;                   // scene units per metre: the IPD scales with it
    Ease ease = Ease::Linear;                   // timing of the segment to the next key
    // Graph parameters keyed here, by name: 1 to 4 components (checked against a pack by
    // check_path_params). A parameter moves between the keys that name it.
    std::map<std::string, std::vector<double>> params;
};

struct CameraSample {
    HeadPose head;
    double world_scale = 1.0;
    double time = 0.0;                          // scene time in seconds
    std::map<std::string, std::vector<double>> params;   // every parameter some key names
};

class CameraPath {
public:
    // Errors name the JSON pointer (/keyframes/2/position). `default_world_scale` is the pack's.
    static std::optional<CameraPath> parse(const nlohmann::json& j, double default_world_scale, Diagnostics& diag);
    static std::optional<CameraPath> load(const std::string& file, double default_world_scale, Diagnostics& diag);

    double fps() const { return fps_; }
    // Frames 0 .. frame_count() - 1 at first key time + n / fps; the last key's time is included.
    int frame_count() const;
    CameraSample sample(int frame) const;
    CameraSample at(double time) const;
    const std::vector<CameraKey>& keys() const { return keys_; }

private:
    std::vector<double> param_at(const std::string& name, double time) const;

    std::vector<CameraKey> keys_;
    double fps_ = 30.0;
    bool smooth_ = true;   // Catmull-Rom through the positions (and targets), else straight lines
};

}  // namespace fg
