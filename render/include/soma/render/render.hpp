#pragma once
// soma::render — off-screen figures: a Scene of primitives -> PNG. Everything in one include.
#include "soma/render/camera.hpp"
#include "soma/render/plot.hpp"
#include "soma/render/color.hpp"
#include "soma/render/image.hpp"
#include "soma/render/primitives.hpp"
#include "soma/render/renderer.hpp"
#include "soma/render/scene.hpp"
#include "soma/render/shapes.hpp"
