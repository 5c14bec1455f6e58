/* libgeardyn: nonlinear dynamics of herringbone gear pairs. The umbrella header. */
#ifndef GEARDYN_H
#define GEARDYN_H

#include "geardyn/gd_version.h"
#include "geardyn/gd_error.h"
#include "geardyn/gd_case.h"
#include "geardyn/gd_pair.h"
#include "geardyn/gd_geometry.h"
#include "geardyn/gd_model.h"
#include "geardyn/gd_modal.h"
#include "geardyn/gd_scene.h"
#include "geardyn/gd_analysis.h"
#include "geardyn/gd_job.h"
#include "geardyn/gd_sim.h"
#include "geardyn/gd_response.h"
#include "geardyn/gd_workprec.h"
#include "geardyn/gd_output.h"
#include "geardyn/gd_spectrum.h"
#include "geardyn/gd_contact.h"
#include "geardyn/gd_compliance.h"
#include "geardyn/gd_sweep.h"
#include "geardyn/gd_periodic.h"
#include "geardyn/gd_continuation.h"
#include "geardyn/gd_basins.h"
#include "geardyn/gd_envelope.h"
#include "geardyn/gd_flank.h"
#include "geardyn/gd_tca.h"
#include "geardyn/gd_ltca.h"
#include "geardyn/gd_excitation.h"
#include "geardyn/gd_optimize.h"
#include "geardyn/gd_dynobj.h"

#endif
