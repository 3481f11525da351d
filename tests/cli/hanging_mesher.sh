#!/bin/sh
# A mesher that never finishes, as Gmsh in METIS's endless loop did.
sleep 600
