// Car body of benchmark C4 (doc/benchmarks.md): a solid, car-like profile in
// the x-y plane extruded 1 m along z; length 2.6 m (front at x = 0, facing
// -x), height 1 m; bonnet and boot at 0.6 m, cabin roof at 1 m, front
// bottom rounded with R1 = 0.2 m, rear top with R2 = 0.3 m.
// Unstructured tetrahedra of size h (0.14 m: about 1200 points, 0.1 m:
// about 2300, 0.07 m: about 6300).  Patches:
//   front   the front face x = 0 (faces the wall)
//   body    everything else
DefineConstant[ h = 0.1 ];
SetFactory("OpenCASCADE");
R1 = 0.2;  R2 = 0.3;  W = 1.0;
Point(1) = {R1, 0, 0};
Point(2) = {2.6, 0, 0};
Point(3) = {2.6, 0.6 - R2, 0};
Point(4) = {2.6 - R2, 0.6 - R2, 0};    // centre of the rear arc
Point(5) = {2.6 - R2, 0.6, 0};
Point(6) = {2.2, 0.6, 0};
Point(7) = {1.85, 1.0, 0};
Point(8) = {1.2, 1.0, 0};
Point(9) = {0.8, 0.6, 0};
Point(10) = {0, 0.6, 0};
Point(11) = {0, R1, 0};
Point(12) = {R1, R1, 0};               // centre of the front arc
Line(1) = {1, 2};
Line(2) = {2, 3};
Circle(3) = {3, 4, 5};
Line(4) = {5, 6};
Line(5) = {6, 7};
Line(6) = {7, 8};
Line(7) = {8, 9};
Line(8) = {9, 10};
Line(9) = {10, 11};
Circle(10) = {11, 12, 1};
Curve Loop(1) = {1:10};
Plane Surface(1) = {1};
ext[] = Extrude{0, 0, W} { Surface{1}; };
Mesh.CharacteristicLengthMin = h;
Mesh.CharacteristicLengthMax = h;
e = 1e-6;
Physical Surface("front") = Surface In BoundingBox{-e, R1 - e, -e, e, 0.6 + e, W + e};
all[] = Surface{:};
body[] = {};
For i In {0 : #all[] - 1}
    bb[] = BoundingBox Surface{all[i]};
    If (!(bb[3] < e && bb[0] > -e))
        body[] += all[i];
    EndIf
EndFor
Physical Surface("body") = body[];
Physical Volume("car") = {ext[1]};
