#pragma once
// Reads a scene file (configs/scenes/*.yaml; every key is commented in the
// shipped files). Top-level keys:
//
//   camera       camera YAML path, relative to the scene file
//   resolution   optional [width, height]: the camera rescaled to this size
//   fps, frames, seed
//   noise        optional: pixel noise sigma in 8-bit units (default 0)
//   anisotropy   optional: anisotropic texture filtering, 1-16 (default 1;
//                sharper road far ahead, about 4x the render time)
//   photos       optional: folder the photo paths are relative to (itself
//                relative to the scene file; default: the scene's folder)
//   street       road_width, pavement_width, start, end, texel
//   sky          optional: zenith, horizon ([r, g, b] 0-255), clouds (0-1)
//   facades      list: image, label, crop [x, y, w, h] (optional), width,
//                position [x, y, z] (bottom centre), facing (degrees)
//   start        position [x, y, z], heading, pitch, roll (degrees)
//   trajectory   list of segments, each `type` + `duration` (+ `ease`):
//                  pan     distance
//                  walk    speed, direction, bob
//                  arc     radius, angle
//                  rotate  yaw, pitch
//                  shake   translation, rotation, frequency
//   handheld     optional: translation, rotation, frequency
//   motion_blur  optional: samples, shutter
//   lighting     optional list of keys: time, scale, shift, temperature
//   cars         optional list: image, label, crop, width, from [x, y],
//                to [x, y], facing, start, speed, period
//   vegetation   optional list: image, label, crop, width, position,
//                facing, sway {amplitude, frequency}
//
// World frame: x along the street, y to the left, z up (metres); the street
// runs along the x axis centred on y = 0.
//
// Every problem — unknown, missing, mistyped or out-of-range key, a photo or
// label map that does not exist or cannot be read, a crop outside its photo,
// a trajectory shorter than the sequence — throws Error with one message
// naming the scene file and the key (e.g. "facades[1].image").
#include <filesystem>

#include "sequences/synth/scene.hpp"

namespace facadeslam::synth {

SceneSpec load_scene(const std::filesystem::path& path);

// Checks that the trajectory lasts until the last frame; `what` names the
// setting to blame in the message (the scene key, or a command-line option
// that changed frames or fps).
void check_trajectory_covers_frames(const SceneSpec& scene, const std::string& what);

}  // namespace facadeslam::synth
