#pragma once
// The toolkit for a program that tracks: include <opf/opf.h>, link opf::opf (find_package(opf)
// or pkg-config opf). No OpenCV, no OpenGL.
//
//   opf::Tracker tracker(opf::make_estimator_factory("opf", opf::EstimatorSettings{}), seed);
//   for (const opf::Frame& frame : frames)
//     for (const opf::Estimate& estimate : tracker.step(frame)) ...
//
// Reading logs and settings files: <opf/io/measurement_log.h>, <opf/io/estimator_settings_yaml.h>.

#include "opf/core/estimate.h"
#include "opf/core/frame.h"
#include "opf/core/tracker.h"
#include "opf/estimators/estimator_settings.h"
#include "opf/estimators/registry.h"
#include "opf/io/estimator_settings_yaml.h"
#include "opf/io/measurement_log.h"
