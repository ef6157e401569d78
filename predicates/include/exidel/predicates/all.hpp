// exidel: every predicate kernel.
#pragma once

#include "exidel/predicates/adaptive.hpp"
#include "exidel/predicates/batch.hpp"
#include "exidel/predicates/construct.hpp"
#include "exidel/predicates/dynamic.hpp"
#include "exidel/predicates/exact.hpp"
#include "exidel/predicates/floating.hpp"
#include "exidel/predicates/kernel.hpp"
#include "exidel/predicates/mpfr.hpp"
#include "exidel/predicates/predicate.hpp"
#include "exidel/predicates/registry.hpp"
#include "exidel/predicates/types.hpp"
#include "exidel/predicates/wrapper.hpp"
