// exidel::testing: generators for fuzzing geometric code with RapidCheck.
#pragma once

#include "exidel/testing/families.hpp"
#include "exidel/testing/generators.hpp"
#include "exidel/testing/generators3d.hpp"
#include "exidel/testing/lattice.hpp"
#include "exidel/testing/point_sets.hpp"
#include "exidel/testing/show.hpp"
#include "exidel/testing/ulp.hpp"
