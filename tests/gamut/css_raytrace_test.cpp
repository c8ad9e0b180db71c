#include <irid/gamut/clip.h>

#include <gtest/gtest.h>
