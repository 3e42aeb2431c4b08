#include "io/units.h"
