#pragma once
// The operations behind the action table, the panels' buttons and the script: every change to the document goes
// through here (so it is undoable and marks the model unsaved), and every failure becomes an error dialog that
// names the file and the problem. No ImGui and no GL here.
// This header gathers them; each part has its own header, named by what it does. The 3D view's export renders, so
// it lives with the viewport (view_export.h, defined in viewport.cpp), not here.
#include "app/autosave.h"       // autosave in the background, recovery after a crash
#include "app/file_browsing.h"  // the file browser opened for a path action; the path used
#include "app/document.h"       // open, save, unsaved changes, units, undo / redo, the window title
#include "app/export_volume.h"  // volumes: the model, thickness, skin depth, X-ray; in the background
#include "app/exports.h"        // binvox, section and X-ray images, X-ray CSV
#include "app/messages.h"       // error dialogs
#include "app/model_jobs.h"     // voxelizing in the background; cancel, busy
#include "app/project.h"        // the document as a project (.vxp): parts, names, colours, placements
#include "app/settings_sync.h"  // params <-> remembered settings
#include "app/skin.h"           // skin removal (peeling) and its memory limit
#include "app/thickness.h"      // thickness, thin walls, hot spots; peel by distance
#include "app/update.h"         // each frame: finished jobs in, derived results out; section, X-ray
