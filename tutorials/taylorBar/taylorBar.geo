// Taylor bar (doc/benchmarks.md, C1): quarter of a cylinder of radius R and
// length L along y, impact face at y = 0, in x >= 0, z >= 0.  Unstructured
// tetrahedra of size h = R/(2 N) (hex = 1: an O-grid of hexahedra, N cells
// along each edge of the quarter section, 25 (N - 1) layers; hex = 2: the
// same O-grid's points split into structured tetrahedra).
// N = 3, 5, 7 give about 2000, 9000 and 24000 points.  Patches:
//   wall        y = 0 (impact face)       top     y = L
//   symmetryX   x = 0                     symmetryZ  z = 0
//   sides       the cylindrical surface
DefineConstant[ R = 3.2e-3, L = 32.4e-3, N = 5, hex = 0 ];
SetFactory("OpenCASCADE");
h = R/(2*N);
e = 1e-3*R;

If (hex == 0)
    Cylinder(1) = {0, 0, 0, 0, L, 0, R};
    Box(2) = {0, 0, 0, 2*R, L, 2*R};
    BooleanIntersection(3) = { Volume{1}; Delete; }{ Volume{2}; Delete; };
    Mesh.CharacteristicLengthMin = h;
    Mesh.CharacteristicLengthMax = h;
    Mesh.Algorithm3D = 1;
Else
    // O-grid: a square core and two curved blocks, extruded in layers
    a = 0.5*R;
    c = R/Sqrt(2);
    Point(1) = {0, 0, 0};  Point(2) = {a, 0, 0};  Point(3) = {a, 0, a};
    Point(4) = {0, 0, a};  Point(5) = {R, 0, 0};  Point(6) = {c, 0, c};
    Point(7) = {0, 0, R};
    Line(1) = {1, 2};  Line(2) = {2, 3};  Line(3) = {3, 4};
    Line(4) = {4, 1};  Line(5) = {2, 5};  Line(6) = {3, 6};
    Line(7) = {4, 7};
    Circle(8) = {5, 1, 6};
    Circle(9) = {6, 1, 7};
    Curve Loop(1) = {1, 2, 3, 4};      Plane Surface(1) = {1};
    Curve Loop(2) = {5, 8, -6, -2};    Plane Surface(2) = {2};
    Curve Loop(3) = {6, 9, -7, -3};    Plane Surface(3) = {3};
    Transfinite Curve{1:9} = N + 1;
    Transfinite Surface{1, 2, 3};
    If (hex == 1)
        Recombine Surface{1, 2, 3};
        Extrude{0, L, 0} { Surface{1, 2, 3}; Layers{25*(N - 1)}; Recombine; }
    Else
        // hex = 2: the same points, triangles extruded to prisms that gmsh
        // splits into three tetrahedra each (structured tets)
        Extrude{0, L, 0} { Surface{1, 2, 3}; Layers{25*(N - 1)}; }
    EndIf
    Coherence;
EndIf

Physical Surface("wall") = Surface In BoundingBox{-e, -e, -e, R + e, e, R + e};
Physical Surface("top") =
    Surface In BoundingBox{-e, L - e, -e, R + e, L + e, R + e};
Physical Surface("symmetryX") =
    Surface In BoundingBox{-e, -e, -e, e, L + e, R + e};
Physical Surface("symmetryZ") =
    Surface In BoundingBox{-e, -e, -e, R + e, L + e, e};
If (hex == 0)
    // the curved face: the only one not flat in x, y or z
    sides[] = {};
    all[] = Surface{:};
    For i In {0 : #all[] - 1}
        bb[] = BoundingBox Surface{all[i]};
        If (bb[3] - bb[0] > e && bb[4] - bb[1] > e && bb[5] - bb[2] > e)
            sides[] += all[i];
        EndIf
    EndFor
    Physical Surface("sides") = sides[];
Else
    c = R/Sqrt(2);
    Physical Surface("sides") = {
        Surface In BoundingBox{c - e, -e, -e, R + e, L + e, c + e},
        Surface In BoundingBox{-e, -e, c - e, c + e, L + e, R + e}};
EndIf
Physical Volume("bar") = Volume{:};
