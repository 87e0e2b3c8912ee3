// voltree: capture trees from photographs as compact volumetric assets and render them.
#include "apps/voltree_app.h"

int main(int argc, char** argv) { return voltree::app::RunVoltree(argc, argv); }
