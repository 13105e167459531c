"""The studio's views, one package each (docs/STUDIO.md): `VIEW` in its __init__.py, its page
side in view.js beside it."""
