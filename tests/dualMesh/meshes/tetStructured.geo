// Structured tetrahedra in a box (transfinite volume, no recombination)
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 2, 1, 1};
Transfinite Curve{:} = 5;
Transfinite Surface{:};
Transfinite Volume{1};
Physical Surface("walls") = {1, 2, 3, 4, 5, 6};
Physical Volume("solid") = {1};
