// Ball for the wall-work test (ctest boundaryConditions.wallWork): radius
// 10 mm at the origin, unstructured tetrahedra of size h, one patch
// 'surface'.  Tets make triangle faces, whose sub-face fluxes blend the
// point's Riemann state with its neighbours' (dualMesh.H); that is where
// the product of averages and the average of products differ.
DefineConstant[ h = 2.5e-3 ];
SetFactory("OpenCASCADE");
Sphere(1) = {0, 0, 0, 10e-3};
Mesh.CharacteristicLengthMin = h;
Mesh.CharacteristicLengthMax = h;
Physical Surface("surface") = Surface{:};
Physical Volume("ball") = {1};
