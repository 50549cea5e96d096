/* halfwing.h must compile on its own in strict C11. */
#include "halfwing.h"
