/* Status names; see types.h. */
#include "se23/types.h"

const char *se23_status_str(se23_status_t status)
{
    switch (status) {
    case SE23_OK:
        return "SE23_OK";
    case SE23_ERR_NULL:
        return "SE23_ERR_NULL";
    case SE23_ERR_NONFINITE:
        return "SE23_ERR_NONFINITE";
    case SE23_ERR_NOT_ROTATION:
        return "SE23_ERR_NOT_ROTATION";
    case SE23_ERR_DOMAIN:
        return "SE23_ERR_DOMAIN";
    case SE23_ERR_DT:
        return "SE23_ERR_DT";
    case SE23_ERR_NOT_SYMMETRIC:
        return "SE23_ERR_NOT_SYMMETRIC";
    case SE23_ERR_NOT_PSD:
        return "SE23_ERR_NOT_PSD";
    case SE23_ERR_DIM:
        return "SE23_ERR_DIM";
    }
    return "SE23_ERR_UNKNOWN";
}
