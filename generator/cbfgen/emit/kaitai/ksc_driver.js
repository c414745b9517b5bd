// Compile a .ksy (given as JSON, converted by cbfgen) with the npm build of
// kaitai-struct-compiler, whose only interface is the API
// compile(lang, ksyObject, importer, debug). Writes every produced file under
// OUTDIR/<lang>/ and exits non-zero on any error or warning. A file whose
// content is unchanged is not rewritten, so its mtime stays and `make` does not
// rebuild the Go and Java testees that depend on it.
// The npm build takes no command-line options: what ksc's --java-package would do is
// done here, from ksc-options.json beside KSY.json (written by cbfgen): the Java parser
// gets its `package` line, as ksc writes it, and goes to the Maven source folder
// java/src/main/java/<package path>/.
//   node ksc_driver.js KSY.json OUTDIR lang...
// Also a module: compileTo(ksyPath, outDir, langs, log) is that one run, for a caller that compiles
// many .ksy in one node process (tests/ksc_serve.py: node's start and ksc's load are most of a run).
'use strict';
const fs = require('fs');
const path = require('path');
const ksc = require('kaitai-struct-compiler');

async function compileTo(ksyPath, outDir, langs, log = console.log) {
  const ksy = JSON.parse(fs.readFileSync(ksyPath, 'utf8'));
  let options = {};
  try {
    options = JSON.parse(fs.readFileSync(path.join(path.dirname(ksyPath), 'ksc-options.json'), 'utf8'));
  } catch (e) {
    if (e.code !== 'ENOENT') throw e;
  }
  const javaPackage = options.java_package || '';
  const importer = { importYaml: (name) => Promise.reject(new Error('no imports expected: ' + name)) };
  for (const lang of langs) {
    const files = await ksc.compile(lang, ksy, importer, false);
    // The Python parser is the package cbf_kaitai (its module cbf.py), so that it never
    // shadows the codec's `cbf` package on a user's path.
    let dir = lang === 'python' ? path.join(outDir, lang, 'cbf_kaitai') : path.join(outDir, lang);
    if (lang === 'java' && javaPackage) dir = path.join(outDir, lang, 'src', 'main', 'java', ...javaPackage.split('.'));
    fs.mkdirSync(dir, { recursive: true });
    for (const name of Object.keys(files).sort()) {
      const target = path.join(dir, name);
      fs.mkdirSync(path.dirname(target), { recursive: true });
      let text = files[name];
      // The npm build takes no --go-package option: name the package here.
      if (lang === 'go' && !/^package /m.test(text)) text = 'package ' + ksy.meta.id + '\n\n' + text;
      // ksc --java-package puts `package X;` after its first comment line, after a blank line.
      if (lang === 'java' && javaPackage && !/^package /m.test(text)) {
        text = text.replace(/^(.*\n)/, `$1\npackage ${javaPackage};\n`);
      }
      let old = null;
      try { old = fs.readFileSync(target, 'utf8'); } catch (e) { old = null; }
      if (old === text) continue;
      fs.writeFileSync(target, text);
      log(`ksc: ${lang}: ${path.relative(process.cwd(), target)}`);
    }
  }
}

function describe(err) {
  const text = err && err.stack ? err.stack : String(err);
  return 'ksc: ' + (Array.isArray(err) ? JSON.stringify(err) : text);
}

module.exports = { compileTo, describe };

if (require.main === module) {
  const [ksyPath, outDir, ...langs] = process.argv.slice(2);
  compileTo(ksyPath, outDir, langs).catch((err) => {
    console.error(describe(err));
    process.exit(1);
  });
}
