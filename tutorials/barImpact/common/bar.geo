// One bar of the bar-impact benchmarks (doc/benchmarks.md, part A): a box
// [x0, x0+L] x [-W/2, W/2]^2 of structured tetrahedra (each hex cell split in
// six; hex = 1: hexahedra), nx cells along the bar and ny across (bump < 1:
// cells graded along the bar, finer towards both ends, gmsh's Bump); hex = 2:
// unstructured tetrahedra (gmsh's Delaunay) of edges about min(L/nx, W/ny),
// whose two ends are meshed independently (two such bars meet through a
// non-matching contact).  Patches:
//   contact  the end facing the other bar (contactEnd = 1: at x0+L, else x0)
//   end      the other end
//   sides    the four lateral faces
// Set parameters with  gmsh -setnumber nx 160 ...
DefineConstant[ x0 = 0, L = 10, W = 1, nx = 80, ny = 2, contactEnd = 1,
                hex = 0, bump = 1 ];

SetFactory("OpenCASCADE");
Box(1) = {x0, -W/2, -W/2, L, W, W};

If (hex == 2)
    Mesh.CharacteristicLengthMin = Min(L/nx, W/ny);
    Mesh.CharacteristicLengthMax = Min(L/nx, W/ny);
Else
    curves[] = Curve{:};
    For i In {0 : #curves[] - 1}
        bb[] = BoundingBox Curve{curves[i]};
        If (bb[3] - bb[0] > L/2 && bump != 1)
            Transfinite Curve{curves[i]} = nx + 1 Using Bump bump;
        ElseIf (bb[3] - bb[0] > L/2)
            Transfinite Curve{curves[i]} = nx + 1;
        Else
            Transfinite Curve{curves[i]} = ny + 1;
        EndIf
    EndFor
    Transfinite Surface{:};
    Transfinite Volume{1};
EndIf
If (hex == 1)
    Recombine Surface{:};
    Recombine Volume{1};
EndIf

// OpenCASCADE box faces: 1 x = x0, 2 x = x0 + L, 3-6 the sides
If (contactEnd == 1)
    Physical Surface("contact") = {2};
    Physical Surface("end") = {1};
Else
    Physical Surface("contact") = {1};
    Physical Surface("end") = {2};
EndIf
Physical Surface("sides") = {3, 4, 5, 6};
Physical Volume("bar") = {1};
