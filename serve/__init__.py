"""`bcc serve`: the compiler and solvers as an HTTP/JSON service with a web viewer (issue 9)."""
