// halfwing.h and halfwing.hpp must compile on their own in strict C++17.
#include "halfwing.h"
#include "halfwing.hpp"
