// Torus of benchmark C2 (doc/benchmarks.md): ring torus in the x-y plane
// (axis z) centred at the origin, outer radius 40 mm, inner radius 30 mm
// (tube radius 5 mm), unstructured tetrahedra of size h.  One patch,
// 'surface'.  h = 1.85, 1.4, 1.12 mm give about 3500, 7600 and 13500
// points (the first three meshes of doc/benchmarks.md).
DefineConstant[ h = 1.85e-3 ];
SetFactory("OpenCASCADE");
Torus(1) = {0, 0, 0, 35e-3, 5e-3};
Mesh.CharacteristicLengthMin = h;
Mesh.CharacteristicLengthMax = h;
Physical Surface("surface") = Surface{:};
Physical Volume("torus") = {1};
