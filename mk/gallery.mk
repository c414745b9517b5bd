# Toolpath gallery (issue #16): `cbf plot` and `cbf stats` of every golden file
# that validates clean, with an index.md showing each image beside its stats.
#   gallery     build/gallery/{NAME.png,NAME.svg,NAME.stats.txt,NAME.stats.json,index.md}
GALLERY := build/gallery
.PHONY: gallery

gallery: generate-py  ## plot + stats of every valid golden file into build/gallery/
	@rm -rf $(GALLERY)
	$(PY) -m cbf.gallery $(GALLERY) conformance/golden/*.cbf
