#pragma once

// The spectral colour-science core of irid: one include for all of it.
#include <irid/color/adaptation.h>
#include <irid/color/colorimeter.h>
#include <irid/color/convert.h>
#include <irid/color/difference.h>
#include <irid/color/illuminant.h>
#include <irid/color/matrix.h>
#include <irid/color/numeric_table.h>
#include <irid/color/observer.h>
#include <irid/color/primaries.h>
#include <irid/color/rgb.h>
#include <irid/color/spaces.h>
#include <irid/color/spectrum.h>
#include <irid/color/types.h>
#include <irid/error.h>
