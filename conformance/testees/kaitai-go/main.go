// Command testee runs the generated Kaitai Go testee (generated/kaitai/go-testee/testee.go).
package main

import (
	"os"

	"cbf-kaitai-testee/cbf"
)

func main() { os.Exit(cbf.RunTestee()) }
