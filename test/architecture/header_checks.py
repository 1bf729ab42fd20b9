"""What the header checks of this folder share: their self-tests' runner and their command line."""
import pathlib
import tempfile


def failed_cases(cases, problems):
    """The self-test cases {name: ({relative path: text}, broken)} whose files, written in a
    temporary folder, `problems` does not judge as expected: broken cases must give a problem."""
    failures = []
    for name, (files, broken) in cases.items():
        with tempfile.TemporaryDirectory() as folder:
            for relative, text in files.items():
                path = pathlib.Path(folder, relative)
                path.parent.mkdir(parents=True, exist_ok=True)
                path.write_text(text + '\n')
            if bool(problems(folder)) != broken:
                failures.append(f'self-test "{name}": expected {"a" if broken else "no"} problem, '
                                f'found {problems(folder)}')
    return failures


def main(argv, problems, self_test):
    """Prints the problems of the folder argv[1] (or of the self-test with --self-test), then their
    count; the exit status is 1 when there is any."""
    found = self_test() if argv[1:] == ['--self-test'] else problems(argv[1])
    for line in found:
        print(line)
    print(f'{len(found)} problem(s)')
    return 1 if found else 0
