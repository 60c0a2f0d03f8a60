"""Real Minecraft: a local flying-squid server, a mineflayer bot driven over JSON lines,
and a state parser from the world to the compiled model (issue 10)."""
