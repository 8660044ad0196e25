// Unstructured tetrahedra in a cylinder
SetFactory("OpenCASCADE");
Cylinder(1) = {0, 0, 0, 0, 0, 2, 0.5};
Mesh.CharacteristicLengthMax = 0.18;
Physical Surface("walls") = {1, 2, 3};
Physical Volume("solid") = {1};
