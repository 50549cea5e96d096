//! The 2D Voronoi diagram and its Delaunay dual.
