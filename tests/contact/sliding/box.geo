// A box [x0, x0+Lx] x [y0, y0+Ly] x [z0, z0+Lz] of structured hexahedra
// (hex = 1) or tetrahedra (each hex split in six), n cells per unit length
// (at least one per side).  Patches: top (z = z0+Lz), bottom (z = z0),
// sides (the other four faces).
DefineConstant[ x0 = 0, y0 = 0, z0 = 0, Lx = 1, Ly = 1, Lz = 1, n = 4,
                hex = 1 ];

SetFactory("OpenCASCADE");
Box(1) = {x0, y0, z0, Lx, Ly, Lz};

curves[] = Curve{:};
For i In {0 : #curves[] - 1}
    bb[] = BoundingBox Curve{curves[i]};
    len = Sqrt((bb[3] - bb[0])^2 + (bb[4] - bb[1])^2 + (bb[5] - bb[2])^2);
    Transfinite Curve{curves[i]} = Max(1, Round(n*len)) + 1;
EndFor
Transfinite Surface{:};
Transfinite Volume{1};
If (hex == 1)
    Recombine Surface{:};
    Recombine Volume{1};
EndIf

// OpenCASCADE box faces: 1-2 x, 3-4 y, 5 z = z0, 6 z = z0 + Lz
Physical Surface("bottom") = {5};
Physical Surface("top") = {6};
Physical Surface("sides") = {1, 2, 3, 4};
Physical Volume("box") = {1};
