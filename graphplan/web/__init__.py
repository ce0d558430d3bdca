"""`graphplan serve`: the lab's web page (docs/serve.md). A thin shell over graphplan.api, the sheets
and teach: the page and its static files (web/static), the HTTP routes (web/app), the work done in
worker processes with a time bound (web/worker, web/jobs) and the forms that write a scene's TOML
(web/templates). Nothing here computes a mechanism itself."""
