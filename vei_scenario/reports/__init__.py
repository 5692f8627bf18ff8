"""Human-readable reports of what vei-scenario did."""
