#include "illum/math/warp.h"
