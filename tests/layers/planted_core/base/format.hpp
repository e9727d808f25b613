// base including only the standard library.
#include <string>
