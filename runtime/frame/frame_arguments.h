#pragma once
// Frame settings as fgplay's commands (render, view, xr) take them on the command line, parsed one
// way, each problem told in one form that names the option: "--knob takes name=value, not 'eps'".
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "frame_settings.h"

namespace fg {

// "--knob name=value", repeated: each sets knobs[name] (a specialization constant by its manifest
// name; whether the pack has it is the frame graph's to say). False, with `error`, on the first bad one.
bool parse_knobs(const std::vector<std::string>& texts, std::map<std::string, double>& knobs, std::string& error);

// "--size WxH": both 1 .. `max`.
bool parse_size(const std::string& text, std::uint32_t max, std::uint32_t& width, std::uint32_t& height,
                std::string& error);

// "--stereo reproject | per-eye | naive".
bool parse_stereo(const std::string& text, StereoMode& out, std::string& error);

}  // namespace fg
