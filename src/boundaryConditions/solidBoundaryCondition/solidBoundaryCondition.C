/*---------------------------------------------------------------------------*\
  solidVertexMBFoam: explicit vertex-centred finite volumes for large-strain
  solid contact dynamics.  License: GPL-3.0-or-later (see LICENSE).
\*---------------------------------------------------------------------------*/

#include "solidBoundaryCondition.H"
#include "checkedInput.H"
#include "syncTools.H"
#include "unitConversion.H"

namespace Foam
{
    defineTypeNameAndDebug(solidBoundaryCondition, 0);
    defineRunTimeSelectionTable(solidBoundaryCondition, dictionary);
}

const Foam::scalar Foam::solidBoundaryCondition::featureAngle = 30;


Foam::solidBoundaryCondition::solidBoundaryCondition
(
    const dualMesh& dual,
    const label patchi,
    const dictionary& dict
)
:
    dual_(dual),
    patchi_(patchi),
    dict_(dict)
{
    const dualMesh::patchSubFaces& sf = dual_.subFaces(patchi_);
    const polyMesh& mesh = dual_.mesh();

    const vectorField meanN(dual_.patchPointNormals(patchi_));

    // Smallest cosine between a sub-face and its point's mean normal
    scalarField minCos(mesh.nPoints(), 1.0);
    forAll(sf.point, s)
    {
        const label i = sf.point[s];
        minCos[i] = min(minCos[i], (sf.area[s] & meanN[i])/mag(sf.area[s]));
    }
    syncTools::syncPointList(mesh, minCos, minEqOp<scalar>(), 1.0);

    const scalar cosFeature = cos(degToRad(featureAngle));
    auto normal = [&](const label i, const vector& N) -> vector
    {
        return (minCos[i] >= cosFeature) ? meanN[i] : N;
    };

    normalPoint_.setSize(sf.size());
    normalPrev_.setSize(sf.size());
    normalNext_.setSize(sf.size());
    forAll(sf.point, s)
    {
        const vector N(sf.area[s]/mag(sf.area[s]));
        normalPoint_[s] = normal(sf.point[s], N);
        normalPrev_[s] = normal(sf.prev[s], N);
        normalNext_[s] = normal(sf.next[s], N);
    }
}


Foam::autoPtr<Foam::solidBoundaryCondition> Foam::solidBoundaryCondition::New
(
    const dualMesh& dual,
    const label patchi,
    const dictionary& dict
)
{
    const word bcType(dict.get<word>("type"));

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(bcType);

    if (!cstrIter.found())
    {
        FatalIOErrorInFunction(dict)
            << "Unknown boundary condition type '" << bcType
            << "' for patch '" << dual.mesh().boundaryMesh()[patchi].name()
            << "'" << nl << "Valid types: "
            << flatOutput(dictionaryConstructorTablePtr_->sortedToc())
            << exit(FatalIOError);
    }

    autoPtr<solidBoundaryCondition> bc(cstrIter()(dual, patchi, dict));
    checkKeywords(dict, bc->keywords());
    return bc;
}


Foam::scalar Foam::solidBoundaryCondition::addFluxes
(
    const UList<point>& x,
    const UList<vector>& v,
    const UList<tensor>& P,
    const UList<tensor>& H,
    const waveData& body,
    const scalar t,
    UList<vector>& Rp,
    UList<tensor>& RF,
    UList<vector>& tB,
    UList<vector>& vB
) const
{
    const dualMesh::patchSubFaces& sf = dual_.subFaces(patchi_);
    const bool keepStates = tB.size();
    scalar power = 0;

    // Contact state of point k seen through the sub-face normal N
    auto state = [&](const label k, const vector& N, vector& tC, vector& vC)
    {
        vector n(H[k] & N);
        const scalar Lambda = mag(n);
        n /= Lambda;
        const waveData w{body.Zp, body.Zs, body.shockMass*Lambda};
        contactState(n, N, x[k], v[k], P[k] & N, w, t, tC, vC);
    };

    forAll(sf.point, s)
    {
        const label i = sf.point[s];
        const scalar magA = mag(sf.area[s]);

        vector tC, vC;
        state(i, normalPoint_[s], tC, vC);

        // The power is the same quadrature of the pointwise power t.v, not
        // the product of the averaged t and v: a fixed frictionless wall or
        // a symmetry plane then does no work, as in the continuum (the
        // product of averages is not zero at a contact perimeter, where an
        // open neighbour approaching the wall meets a closed point's
        // pressure, and would hide numerical dissipation as external work)
        scalar pC = tC & vC;
        const scalar w = sf.nbrWeight[s];
        if (w > 0)
        {
            vector tP, vP, tN, vN;
            state(sf.prev[s], normalPrev_[s], tP, vP);
            state(sf.next[s], normalNext_[s], tN, vN);
            tC = (1 - 2*w)*tC + w*(tP + tN);
            vC = (1 - 2*w)*vC + w*(vP + vN);
            pC = (1 - 2*w)*pC + w*((tP & vP) + (tN & vN));
        }

        Rp[i] += magA*tC;
        RF[i] += vC*sf.area[s];
        power += magA*pC;
        if (keepStates)
        {
            tB[s] = tC;
            vB[s] = vC;
        }
    }

    return power;
}


void Foam::solidBoundaryCondition::describe(Ostream& os) const
{
    os  << dict_.get<word>("type");
}


// ************************************************************************* //
