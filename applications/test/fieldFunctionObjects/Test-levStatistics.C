/*---------------------------------------------------------------------------*\
  flapFoam: free-flight simulation of flapping-wing drones on OpenFOAM v1912
-------------------------------------------------------------------------------
    Copyright (C) 2025-2026 flapFoam developers
-------------------------------------------------------------------------------
License
    This file is part of flapFoam, derived from OpenFOAM.

    flapFoam is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by
    the Free Software Foundation, either version 3 of the License, or
    (at your option) any later version.

    flapFoam is distributed in the hope that it will be useful, but WITHOUT
    ANY WARRANTY; without even the implied warranty of MERCHANTABILITY or
    FITNESS FOR A PARTICULAR PURPOSE.  See the GNU General Public License
    for more details.

    You should have received a copy of the GNU General Public License
    along with flapFoam (COPYING).  If not, see <http://www.gnu.org/licenses/>.

Description
    levStatistics::sum on a Lamb-Oseen vortex whose gradient is sampled at
    the centres of a grid of cells (the function object's sums without a
    mesh): the vortex about the span axis, u_theta = G0/(2 pi r)
    (1 - exp(-r^2/rc^2)), has Q = (u_theta/r) du_theta/dr > 0 inside
    r_m = 1.12091 rc (du_theta/dr = 0: 1 + 2x = exp(x), x = r_m^2/rc^2 =
    1.25643) and spanwise vorticity > 0 everywhere, so V' = pi r_m^2 L and
    Gamma = G0 (1 - exp(-x)) L (L the length along the axis):
      - the sums within 1 % of these (cells of rc/20; measured -0.69 %
        and -0.34 %);
      - the same vortex turned by a rotation, summed about the turned axis:
        the same sums to 1e-12 (Q and omega . axis are invariants);
      - the vortex turning the other way: no cell (omega . axis < 0);
      - rigidFit::rotation recovers a rotation from rotated and shifted
        points to 1e-12, and gives a proper rotation (det 1).

\*---------------------------------------------------------------------------*/

#include "levStatistics.H"
#include "rigidFit.H"
#include "quaternion.H"
#include "Random.H"
#include "mathematicalConstants.H"

#include <gtest/gtest.h>

using namespace Foam;

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using constant::mathematical::pi;

//- A Lamb-Oseen vortex about the y axis sampled at cell centres
struct vortexGrid
{
    List<tensor> gradU;
    scalarField V;
    labelList cells;
};

//- OpenFOAM's grad U (G_ij = d u_j / d x_i) of the vortex u = f(r)
//- (z, 0, -x), r^2 = x^2 + z^2 (circulation G0 about +y, core rc)
tensor lambOseenGrad(const point& p, const scalar G0, const scalar rc)
{
    const scalar x = p.x(), z = p.z();
    const scalar r2 = x*x + z*z, r = Foam::sqrt(r2);
    const scalar e = Foam::exp(-r2/(rc*rc));
    const scalar f = G0/(2*pi)*(1 - e)/r2;
    const scalar df =
        G0/(2*pi)*((2*r/(rc*rc))*e*r2 - 2*r*(1 - e))/(r2*r2);

    tensor G(Zero);
    G.xx() = df*x*z/r;
    G.zx() = f + df*z*z/r;
    G.xz() = -f - df*x*x/r;
    G.zz() = -df*x*z/r;
    return G;
}

//- n x n cells of size h in x and z (centres off r = 0), one layer of
//- thickness h in y; the field turned by R (G' = R G R^T)
vortexGrid sample
(
    const label n,
    const scalar h,
    const scalar G0,
    const scalar rc,
    const tensor& R = tensor::I
)
{
    vortexGrid g;
    g.gradU.setSize(n*n);
    g.V.setSize(n*n, h*h*h);
    g.cells = identity(n*n);
    for (label i = 0; i < n; ++i)
    {
        for (label k = 0; k < n; ++k)
        {
            const point p((i + 0.5 - n/2)*h, 0, (k + 0.5 - n/2)*h);
            g.gradU[i*n + k] = R & lambOseenGrad(p, G0, rc) & R.T();
        }
    }
    return g;
}

const scalar rc = 0.01;
const scalar G0 = 0.05;
const scalar xm = 1.2564312086261696;       // 1 + 2x = exp(x)

} // End anonymous namespace


// * * * * * * * * * * * * * * * * * Tests * * * * * * * * * * * * * * * * //

TEST(levStatistics, lambOseenVolumeAndCirculation)
{
    ASSERT_NEAR(1 + 2*xm, Foam::exp(xm), 1e-12);

    const scalar h = rc/20;
    const vortexGrid g(sample(160, h, G0, rc));
    const functionObjects::levStatistics::sums s =
        functionObjects::levStatistics::sum(g.gradU, g.V, g.cells, vector(0, 1, 0));

    const scalar L = h;
    const scalar volume = pi*xm*rc*rc*L;
    const scalar circulation = G0*(1 - Foam::exp(-xm))*L;
    EXPECT_NEAR(s.volume/volume, 1, 0.01);
    EXPECT_NEAR(s.circulation/circulation, 1, 0.01);
    EXPECT_GT(s.nCells, 1000);
}


TEST(levStatistics, rotatedVortexSameSums)
{
    const tensor R(quaternion(normalised(vector(0.3, -0.8, 0.5)), 1.1).R());
    const scalar h = rc/10;
    const vortexGrid g(sample(80, h, G0, rc));
    const vortexGrid gR(sample(80, h, G0, rc, R));

    typedef functionObjects::levStatistics lev;
    const lev::sums s = lev::sum(g.gradU, g.V, g.cells, vector(0, 1, 0));
    const lev::sums sR = lev::sum(gR.gradU, gR.V, gR.cells, R & vector(0, 1, 0));

    EXPECT_EQ(s.nCells, sR.nCells);
    EXPECT_NEAR(sR.volume/s.volume, 1, 1e-12);
    EXPECT_NEAR(sR.circulation/s.circulation, 1, 1e-12);
}


TEST(levStatistics, vortexTurningTheOtherWayNotCounted)
{
    const vortexGrid g(sample(40, rc/10, -G0, rc));
    const functionObjects::levStatistics::sums s =
        functionObjects::levStatistics::sum(g.gradU, g.V, g.cells, vector(0, 1, 0));
    EXPECT_EQ(s.nCells, 0);
    EXPECT_EQ(s.volume, 0);
}


TEST(rigidFit, recoversRotation)
{
    const tensor R(quaternion(normalised(vector(-0.2, 0.9, 0.4)), 2.3).R());
    Random rnd(7);
    pointField p0(50), p(50);
    forAll(p0, i)
    {
        p0[i] = rnd.sample01<vector>();
        p[i] = (R & p0[i]) + vector(1, -2, 3);
    }
    const tensor fit(rigidFit::rotation(p0, p));
    EXPECT_LT(mag(fit - R), 1e-12);
    EXPECT_NEAR(det(fit), 1, 1e-12);
}


// ************************************************************************* //
