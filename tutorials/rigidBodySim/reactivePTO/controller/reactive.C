/*---------------------------------------------------------------------------*\
    Rigid-body dynamics for OpenFOAM v1912
    Copyright (C) the authors of this project (its git history names them)
-------------------------------------------------------------------------------
License
    This file is part of the rigid-body dynamics for OpenFOAM v1912.

    It is free software: you can redistribute it and/or modify it under the
    terms of the GNU General Public License as published by the Free
    Software Foundation, either version 3 of the License, or (at your
    option) any later version.

    It is distributed in the hope that it will be useful, but WITHOUT ANY
    WARRANTY; without even the implied warranty of MERCHANTABILITY or
    FITNESS FOR A PARTICULAR PURPOSE.  See the GNU General Public License
    for more details.

    You should have received a copy of the GNU General Public License along
    with it (the file LICENSE at the top of the project).  If not, see
    <https://www.gnu.org/licenses/>.
-------------------------------------------------------------------------------
Class
    Foam::RBD::ptoControllers::reactive

Description
    An example of a user's PTO controller (tutorial reactivePTO): reactive
    (complex-conjugate) control tuned to one period.  Given the mass m
    (or inertia) and the stiffness K the PTO's degree of freedom sees, it
    sets the PTO's stiffness to m omega^2 - K, so that the spring and the
    inertia cancel at omega = 2 pi/period, and its damping to the damping
    given.  A negative stiffness (the period longer than the natural one)
    feeds power back into the motion at times: reactive control.

    It reads the joint's state each step but keeps its coefficients: a
    controller of your own can change them with the state and time.

Usage
    \verbatim
    controller
    {
        type        reactive;
        period      3.355;      // [s] the period it is tuned to
        mass        10000;      // [kg or kg m^2]
        stiffness   0;          // [N/m or N m/rad] the plant's spring
        damping     20000;      // [N s/m or N m s/rad]
    }
    \endverbatim

SourceFiles
    reactive.C

\*---------------------------------------------------------------------------*/

#include "ptoController.H"
#include "addToRunTimeSelectionTable.H"
#include "mathematicalConstants.H"

namespace Foam
{
namespace RBD
{
namespace ptoControllers
{

class reactive
:
    public ptoController
{
    // Private data

        //- The stiffness and damping it sets
        scalar stiffness_;
        scalar damping_;


public:

    //- Runtime type information
    TypeName("reactive");


    // Constructors

        //- Construct from the controller's dictionary
        reactive(const dictionary& dict)
        {
            const scalar period = dict.get<scalar>("period");
            const scalar mass = dict.get<scalar>("mass");
            if (!(period > 0) || !(mass > 0))
            {
                FatalIOErrorInFunction(dict)
                    << "Entries period " << period << " and mass " << mass
                    << " of the reactive controller must be positive" << nl
                    << exit(FatalIOError);
            }
            const scalar omega = constant::mathematical::twoPi/period;
            stiffness_ = mass*sqr(omega) - dict.get<scalar>("stiffness");
            damping_ = dict.get<scalar>("damping");
            Info<< "reactive PTO controller: stiffness " << stiffness_
                << ", damping " << damping_ << endl;
        }

        //- Return a clone
        virtual autoPtr<ptoController> clone() const
        {
            return autoPtr<ptoController>(new reactive(*this));
        }


    // Member Functions

        //- Set the coefficients for the next step
        virtual void update
        (
            const scalar t,
            const scalar deltaT,
            const scalar q,
            const scalar qDot,
            coefficients& c
        )
        {
            c.stiffness = stiffness_;
            c.damping = damping_;
        }
};


defineTypeNameAndDebug(reactive, 0);
addToRunTimeSelectionTable(ptoController, reactive, dictionary);

} // End namespace ptoControllers
} // End namespace RBD
} // End namespace Foam


// ************************************************************************* //
