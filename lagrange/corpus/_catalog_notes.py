"""Decisions for the catalog's [FULL] cases the corpus does not cover (see :mod:`lagrange.corpus.coverage`).

``NOTES[key] = (status, reason)``. Status is one of :data:`STATUSES`: ``"not checkable"`` (the answer is a
definition, a proof or a count nothing in a System produces), ``"catalog gap"`` (the catalog lacks what a check
needs: the statement, the figure's geometry, or the system referred to), ``"needs <capability> (in progress)"``
(another branch adds the capability), or ``"checkable: to add"`` (a case still to be added to the corpus).
``tests/problems/test_coverage.py`` requires a decision for every uncovered [FULL] case and none for a covered one.
"""

NOT_CHECKABLE = "not checkable"
GAP = "catalog gap"
TO_ADD = "checkable: to add"
STATUSES = (NOT_CHECKABLE, GAP, TO_ADD)

_TRANSFORM = ("the answer is a set of transformation equations, which a problem states (as its coordinates) rather "
              "than derives; there is no result of the System to compare")
_PROOF = "a proof of an identity of vector algebra; the book states no result of a particular system to compare"
_PROPERTY = ("a property test of the method, not a book answer: it holds for every system and is exercised by the "
             "test suite and by the corpus answers of that kind")

NOTES: dict[str, tuple[str, str]] = {
    "p2.1": (NOT_CHECKABLE, f"Polar to oblique coordinates: {_TRANSFORM}."),
    "p2.4": (NOT_CHECKABLE, f"Centre-of-mass and relative coordinates of two masses: {_TRANSFORM}; the yes/no "
             "('are q1, y3 inertial?') is qualitative. The same coordinates are checked through T in P2.22."),
    "p2.5": (NOT_CHECKABLE, f"Axes on two nested tables in an accelerating car: {_TRANSFORM}."),
    "p2.8": (NOT_CHECKABLE, f"Spherical coordinates attached to a car on a circular track: {_TRANSFORM}."),
    "p2.12": (GAP, "Only the answer key's counts (5, 10) are transcribed; the problem's statement is not in the "
              "catalog."),
    "p2.17": (GAP, "Three hinged rods (Fig. 2-27): the answer gives x_2 and then 'etc.', and the figure's "
              "geometry is not available, so T cannot be rebuilt independently."),
    "p2.19": (GAP, "Monkeys climbing the Fig. 2-9 ropes: which rope each climbs and the R_2 θ term need the "
              "figure, which the catalog does not describe; the printed T cannot be rebuilt independently."),
    "p2.21": (GAP, "Fig. 2-15 pulleys in s-coordinates: the figure's rope and pulley layout is not in the "
              "catalog; the printed T cannot be rebuilt independently."),
    "p4.24": (GAP, "P4.10 by D'Alembert's equation, 'same answer as P4.10': P4.10's answer is not transcribed in "
              "the catalog (its system is in the corpus as P13.16/P16.7, whose answers are checked)."),
    "ex6.7": (NOT_CHECKABLE, "The general method for a board on a viscous film (the δW integrand of (6.8)); its "
              "instances Ex 6.8 (rectangle) and Ex 6.12 (any shape) are in the corpus."),
    "p8.1": (NOT_CHECKABLE, f"Prove (8.0), the direction cosines of the normal to a plane: {_PROOF}."),
    "p8.2": (NOT_CHECKABLE, f"v² = ω²h² for two superposed rotations: {_PROOF}."),
    "p9.17": (GAP, "Derive Ex 9.7 (6), (7) from the inertial forces: Ex 9.7's equations are not transcribed "
              "in the catalog."),
    "p9.22": (NOT_CHECKABLE, f"Angular momentum about a line is the projection of the vector: {_PROOF}."),
    "p9.23": (NOT_CHECKABLE, f"Angular momentum about X1 with O at the c.m.: {_PROOF}."),
    "p9.24": (NOT_CHECKABLE, f"T with principal axes in a moving frame and the θ equation equal to (9.17): "
              f"{_PROOF}."),
    "p10.5": (GAP, "Prove T and V in normal coordinates 'for Ex 10.9': Ex 10.9 is not transcribed in the "
              "catalog."),
    "p10.17": (GAP, "Drag on the spheres of P10.16: P10.16's system (its figure and geometry r, s, R) is not "
               "in the catalog, so the printed P cannot be rebuilt."),
    "ex12.7": (GAP, "τ_α of Ex 12.6 by Euler's equations: Ex 12.6 (T with products of inertia and three "
               "angles) is not transcribed in the catalog."),
    "app.a8m": (NOT_CHECKABLE, f"Composition of direction-cosine matrices γ = αβ: {_PROPERTY} "
                "(tests/test_rigid_body.py, rotation sequences against their matrix)."),
    "sec18.fq": (NOT_CHECKABLE, f"F_q = Σ F·∂r/∂q against virtual work: {_PROPERTY} (every GeneralizedForces "
                 "answer)."),
    "sec18.orthogonality": (NOT_CHECKABLE, f"Orthogonality relations of Table A.1: {_PROPERTY} "
                            "(tests/test_inertia.py, the z-x-z matrix is a rotation)."),
    "sec18.t-decomposition": (NOT_CHECKABLE, f"T = Σ A q̇q̇ + Σ B q̇ + C from r_i(q, t): {_PROPERTY} (every "
                              "EnergySplit answer, e.g. (2.50))."),
}
