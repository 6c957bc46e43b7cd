GOCAD Model3d 1
HEADER {
name: m
}
END
