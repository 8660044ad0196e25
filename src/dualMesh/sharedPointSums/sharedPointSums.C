/*---------------------------------------------------------------------------*\
  solidVertexMBFoam: explicit vertex-centred finite volumes for large-strain
  solid contact dynamics.  License: GPL-3.0-or-later (see LICENSE).
\*---------------------------------------------------------------------------*/

#include "sharedPointSums.H"
#include "globalMeshData.H"
#include "globalIndex.H"
#include "syncTools.H"
#include "Map.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * //

Foam::sharedPointSums::sharedPointSums(const polyMesh& mesh)
:
    slot_(mesh.nPoints(), -1),
    nShared_(0),
    procs_(),
    procSlots_(),
    nBelow_(0),
    buffer_()
{
    if (!Pstream::parRun())
    {
        return;
    }

    // One number per shared point, the same on all its copies: the
    // smallest of the copies' global numbers among the coupled points
    const labelList& coupled = mesh.globalData().coupledPatch().meshPoints();
    const globalIndex numbering(coupled.size());
    labelList id(coupled.size());
    forAll(id, k)
    {
        id[k] = numbering.toGlobal(k);
    }
    syncTools::syncPointList(mesh, coupled, id, minEqOp<label>(), labelMax);

    // Every processor's numbers (once: the lists are those of the coupled
    // points)
    List<labelList> ids(Pstream::nProcs());
    ids[Pstream::myProcNo()] = id;
    Pstream::gatherList(ids);
    Pstream::scatterList(ids);

    // Slots in the order of the numbers
    labelList order(sortedOrder(id));
    Map<label> slotOf(2*id.size());
    for (const label k : order)
    {
        slot_[coupled[k]] = nShared_;
        slotOf.insert(id[k], nShared_);
        ++nShared_;
    }

    // Per other processor: the numbers both hold, ascending
    DynamicList<label> procs;
    DynamicList<labelList> procSlots;
    forAll(ids, proci)
    {
        if (proci == Pstream::myProcNo())
        {
            continue;
        }
        DynamicList<label> both;
        for (const label n : ids[proci])
        {
            if (slotOf.found(n))
            {
                both.append(n);
            }
        }
        if (both.empty())
        {
            continue;
        }
        Foam::sort(both);
        labelList slots(both.size());
        forAll(both, m)
        {
            slots[m] = slotOf[both[m]];
        }
        if (proci < Pstream::myProcNo())
        {
            ++nBelow_;
        }
        procs.append(proci);
        procSlots.append(slots);
    }
    procs_.transfer(procs);
    procSlots_.transfer(procSlots);
}


// ************************************************************************* //
