"""Analysis tools: small oscillations, steady motion and the Routhian, driving forces and statics,
Hamilton's equations and principle."""
