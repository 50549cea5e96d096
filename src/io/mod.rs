//! Reading and writing meshes: OBJ (tobj), OFF, PLY.
